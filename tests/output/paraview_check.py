"""Opens a results sidecar the way a ParaView user does and checks what they would see.

Usage (ParaView's own Python, under a virtual X server):
    xvfb-run -a pvpython paraview_check.py RUN.xmf STEPS POINTS CELLS FRAME.png BOXES

With the reader ParaView picks by itself (OpenDataFile, the XDMF3 reader for .xmf) it checks:
the number of time steps; at the first, middle and last step the points and cells of all blocks
together, BOXES rigid bodies drawn as hexahedra, and the point data (beams: arc_length and
velocity; boxes and nodes: velocity); that the beams move; that the boxes keep their edges (the
slider_crank's 2 cm cube); and a frame rendered at the last step, coloured by velocity, that is not blank. Prints one
line per check and exits 1 at the first failure. paraview_check.cmake runs it and also fails on
any error or warning ParaView printed.
"""
import sys

from paraview import servermanager
from paraview.simple import (ColorBy, GetActiveViewOrCreate, OpenDataFile, Render, ResetCamera,
                             SaveScreenshot, Show)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON, VTK_POLY_LINE, VTK_POLY_VERTEX
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
    """'beam' for a polyline, 'nodes' for a point cloud, 'box' for a rigid body's hexahedron (VTK
    cell types 4, 2 and 12)."""
    types = {dataset.GetCellType(i) for i in range(dataset.GetNumberOfCells())}
    return {frozenset({VTK_POLY_LINE}): "beam", frozenset({VTK_POLY_VERTEX}): "nodes",
            frozenset({VTK_HEXAHEDRON}): "box"}.get(frozenset(types), str(types))


def point_arrays(dataset):
    data = dataset.GetPointData()
    return {data.GetArrayName(i) for i in range(data.GetNumberOfArrays())}


path, steps, points, cells, frame = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
boxes = int(sys.argv[6])

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
    check(kinds == ["beam"] * (len(blocks) - 1 - boxes) + ["box"] * boxes + ["nodes"],
          f"t = {t:g} s: blocks {kinds}: polylines, {boxes} boxes and nodes")
    for block in blocks:
        expected = {"arc_length", "velocity"} if kind(block) == "beam" else {"velocity"}
        check(point_arrays(block) == expected, f"t = {t:g} s: a {kind(block)} block has point data {sorted(expected)}")
    bounds.append([b for block in blocks for b in block.GetBounds()])
check(bounds[0] != bounds[-1], "the beams move between the first and the last step")
# A box is a rigid body: its 8 vertices x + R c keep their distances whatever the step.
for t in (times[0], times[-1]):
    reader.UpdatePipeline(t)
    for block in leaves(servermanager.Fetch(reader)):
        if kind(block) == "box":
            corners = vtk_to_numpy(block.GetPoints().GetData())
            edges = sorted(round(float(((corners[i] - corners[j]) ** 2).sum() ** 0.5), 9)
                           for i, j in ((0, 1), (0, 3), (0, 4)))
            check(edges == [0.02, 0.02, 0.02], f"t = {t:g} s: the slider's box has edges {edges} m (a 2 cm cube)")

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
