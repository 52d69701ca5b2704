# Issue 9: the results of an example open in ParaView as they are. Runs slider_crank for 0.01 s,
# then ParaView's own Python under a virtual X server on its sidecar (paraview_check.py: time
# steps, points and cells per step, point data, a rendered frame that is not blank), and fails if
# ParaView printed any error or warning. Missing tools are a failure, not a skip:
# `scripts/setup.sh --test` installs them (paraview, python3-paraview, xvfb).
#
#   cmake -DEXAMPLE=<slider_crank> -DCHECK_SCRIPT=<paraview_check.py> -DVIRTUAL_DISPLAY=<virtual_display.py>
#         -DWORK_DIR=<dir> -P paraview_check.cmake

find_program(PVPYTHON pvpython)
find_program(XVFB Xvfb)
find_program(PYTHON3 python3)
if(NOT PVPYTHON OR NOT XVFB OR NOT PYTHON3)
  message(FATAL_ERROR "pvpython (${PVPYTHON}), Xvfb (${XVFB}) or python3 (${PYTHON3}) not found: run "
                      "scripts/setup.sh --test, which installs Debian's paraview, python3-paraview and xvfb")
endif()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
execute_process(COMMAND "${EXAMPLE}" --t-end 0.01 --h 5e-4 --out "${WORK_DIR}"
  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE errors TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXAMPLE} failed (${status}): ${errors}")
endif()

# One CSV row per recorded step after the header. Per step the sidecar holds slider_crank's two
# rods (6 elements each: 61 centerline points, one polyline), the slider's box (8 vertices, one
# hexahedron) and its 19 nodes (9 control points per rod and the slider, one vertex each):
# 2 × 61 + 8 + 19 = 149 points, 2 + 1 + 19 = 22 cells.
file(STRINGS "${WORK_DIR}/slider_crank.csv" rows)
list(LENGTH rows row_count)
math(EXPR steps "${row_count} - 1")

# The render needs an X server; virtual_display.py starts one that is ready before pvpython runs
# and does not reset between ParaView's capability probe and its render window (the cause of "bad
# X server connection": its docstring), and stops it on every path. pvpython runs without MPI: a
# serial check needs none, and Open MPI's start-up probes X displays and may print warnings.
execute_process(
  COMMAND "${PYTHON3}" "${VIRTUAL_DISPLAY}" "${PVPYTHON}" --no-mpi "${CHECK_SCRIPT}" "${WORK_DIR}/slider_crank.xmf"
          ${steps} 149 22 "${WORK_DIR}/frame.png" 1
  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors TIMEOUT 150)
message("${output}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "ParaView's check failed (${status}):\n${errors}")
endif()
# ParaView's log marks errors and warnings with ERR| and WARN|; the XDMF libraries print their
# complaints ("Skipping unrecognized array type", "Cannot find DataItem") straight to stderr.
string(REGEX MATCHALL "[^\n]*(ERR\\||WARN\\||[Ee]rror|[Ww]arning|Skipping|Cannot find|HDF5-DIAG)[^\n]*" complaints
       "${output}\n${errors}")
if(complaints)
  string(REPLACE ";" "\n" complaints "${complaints}")
  message(FATAL_ERROR "ParaView printed errors or warnings:\n${complaints}")
endif()
