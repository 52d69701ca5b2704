"""Opens a results sidecar the way a ParaView user does and checks what they would see.

Usage (ParaView's own Python, under a virtual X server):
    xvfb-run -a pvpython paraview_check.py RUN.xmf STEPS POINTS CELLS FRAME.png

With the reader ParaView picks by itself (OpenDataFile, the XDMF3 reader for .xmf) it checks:
the number of time steps; at the first, middle and last step the points and cells of all blocks
together and the point data (beams: arc_length and velocity; nodes: velocity); that the beams
move; and a frame rendered at the last step, coloured by velocity, that is not blank. Prints one
line per check and exits 1 at the first failure. paraview_check.cmake runs it and also fails on
any error or warning ParaView printed.
"""
import sys

from paraview import servermanager
from paraview.simple import (ColorBy, GetActiveViewOrCreate, OpenDataFile, Render, ResetCamera,
                             SaveScreenshot, Show)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import VTK_POLY_LINE, VTK_POLY_VERTEX
from vtkmodules.vtkIOImage import vtkPNGReader


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        sys.exit(1)


def leaves(block):
    """The datasets of a composite dataset (blocks and pieces, nested)."""
    if block.IsA("vtkMultiPieceDataSet"):
        for i in range(block.GetNumberOfPieces()):
            yield from leaves(block.GetPiece(i))
    elif block.IsA("vtkMultiBlockDataSet"):
        for i in range(block.GetNumberOfBlocks()):
            yield from leaves(block.GetBlock(i))
    else:
        yield block


def kind(dataset):
    """'beam' for a polyline, 'nodes' for a point cloud (VTK cell types 4 and 2)."""
    types = {dataset.GetCellType(i) for i in range(dataset.GetNumberOfCells())}
    return {frozenset({VTK_POLY_LINE}): "beam", frozenset({VTK_POLY_VERTEX}): "nodes"}.get(frozenset(types), str(types))


def point_arrays(dataset):
    data = dataset.GetPointData()
    return {data.GetArrayName(i) for i in range(data.GetNumberOfArrays())}


path, steps, points, cells, frame = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]

reader = OpenDataFile(path)
check(reader is not None, f"ParaView opens {path}")
check(reader.GetXMLName().startswith("Xdmf3Reader"), f"with its XDMF3 reader ({reader.GetXMLName()})")
times = list(reader.TimestepValues)
check(len(times) == steps, f"{len(times)} time steps, expected {steps}")

bounds = []
for t in (times[0], times[len(times) // 2], times[-1]):
    reader.UpdatePipeline(t)
    blocks = list(leaves(servermanager.Fetch(reader)))
    total_points = sum(block.GetNumberOfPoints() for block in blocks)
    total_cells = sum(block.GetNumberOfCells() for block in blocks)
    check((total_points, total_cells) == (points, cells),
          f"t = {t:g} s: {total_points} points and {total_cells} cells, expected {points} and {cells}")
    kinds = sorted(kind(block) for block in blocks)
    check(kinds == ["beam"] * (len(blocks) - 1) + ["nodes"], f"t = {t:g} s: blocks {kinds}: polylines and nodes")
    for block in blocks:
        expected = {"velocity"} if kind(block) == "nodes" else {"arc_length", "velocity"}
        check(point_arrays(block) == expected, f"t = {t:g} s: a {kind(block)} block has point data {sorted(expected)}")
    bounds.append([b for block in blocks for b in block.GetBounds()])
check(bounds[0] != bounds[-1], "the beams move between the first and the last step")

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [480, 360]
view.ViewTime = times[-1]
view.OrientationAxesVisibility = 0
display = Show(reader, view)
display.LineWidth = 3.0
ColorBy(display, ("POINTS", "velocity", "Magnitude"))
ResetCamera(view)
Render(view)
SaveScreenshot(frame, view, ImageResolution=[480, 360])

png = vtkPNGReader()
png.SetFileName(frame)
png.Update()
image = png.GetOutput()
pixels = vtk_to_numpy(image.GetPointData().GetScalars()).astype(float)
background = pixels[0]
drawn = int((abs(pixels - background).sum(axis=1) > 30).sum())
check(drawn > 500, f"the frame at t = {times[-1]:g} s draws {drawn} of {len(pixels)} pixels (not blank)")
colours = len({tuple(p) for p in pixels.astype(int).tolist()})
check(pixels.std(axis=0).max() > 2 and colours > 10,
      f"its pixels vary: standard deviation {pixels.std(axis=0).max():.1f}, {colours} colours (velocity colour map)")
