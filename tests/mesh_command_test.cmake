# `--mesh` end to end (run by CTest as a script):
#   cmake -DAMLS=<amls> -DSCENE=<clover2d.json> -DWORK_DIR=<dir> -P mesh_command_test.cmake
# amls resample --mesh writes a closed triangle mesh of a resampled octahedron as
# PLY and OBJ, amls deform --mesh a closed polyline of a 2D scene's last frame,
# and a bad mesh path fails before any work with no file left behind.
include("${CMAKE_CURRENT_LIST_DIR}/amls_command_checks.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# Runs amls with the arguments; it must succeed and print `expected`.
function(amls_prints expected)
  execute_process(COMMAND "${AMLS}" ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "amls ${ARGN} failed (${code}):\n${out}${err}")
  endif()
  string(FIND "${out}" "${expected}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "amls ${ARGN}: expected '${expected}' in the output, got:\n${out}${err}")
  endif()
endfunction()

# The file at `path` begins with `start`.
function(check_start path start)
  file(READ "${path}" head LIMIT 200)
  string(FIND "${head}" "${start}" position)
  if(NOT position EQUAL 0)
    message(FATAL_ERROR "${path} begins with '${head}', expected '${start}'")
  endif()
endfunction()

file(WRITE "${WORK_DIR}/octahedron.obj"
  "v 0.9 0.5 0.5\nv 0.1 0.5 0.5\nv 0.5 0.9 0.5\nv 0.5 0.1 0.5\nv 0.5 0.5 0.9\nv 0.5 0.5 0.1\n"
  "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n")
amls_prints("triangles, closed, wrote ${WORK_DIR}/octahedron_mesh.ply"
            resample "${WORK_DIR}/octahedron.obj" --grid 32 --out "${WORK_DIR}/octahedron.ply"
            --mesh "${WORK_DIR}/octahedron_mesh.ply")
check_start("${WORK_DIR}/octahedron_mesh.ply" "ply\nformat binary_little_endian 1.0\ncomment amls dim 3\n")
amls_prints("triangles, closed, wrote ${WORK_DIR}/octahedron_mesh.obj"
            resample "${WORK_DIR}/octahedron.obj" --grid 32 --variant interpolated --out "${WORK_DIR}/octahedron.ply"
            --mesh "${WORK_DIR}/octahedron_mesh.obj")
check_start("${WORK_DIR}/octahedron_mesh.obj" "# amls surface mesh (3D)")
# STL, for slicers: written, and read back as a closed mesh to resample.
amls_prints("triangles, closed, wrote ${WORK_DIR}/octahedron_mesh.stl"
            resample "${WORK_DIR}/octahedron.obj" --grid 32 --out "${WORK_DIR}/octahedron.ply"
            --mesh "${WORK_DIR}/octahedron_mesh.stl")
check_start("${WORK_DIR}/octahedron_mesh.stl" "amls surface mesh, ")
amls_prints("triangles, closed, wrote ${WORK_DIR}/again.ply"
            resample "${WORK_DIR}/octahedron_mesh.stl" --grid 32 --out "${WORK_DIR}/again_points.ply"
            --mesh "${WORK_DIR}/again.ply")
# The mesh reads back as a mesh: amls renders it.
execute_process(COMMAND "${AMLS}" render "${WORK_DIR}/octahedron_mesh.obj" --out "${WORK_DIR}/octahedron.png"
                        --size 32x32 RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT err STREQUAL "")
  message(FATAL_ERROR "amls render of the written mesh: ${code}\n${out}${err}")
endif()

amls_prints("segments, closed, wrote ${WORK_DIR}/clover.obj"
            deform "${SCENE}" --max-steps 1 --mesh "${WORK_DIR}/clover.obj")
check_start("${WORK_DIR}/clover.obj" "# amls surface mesh (2D)")

amls_fails("expected .obj, .ply or .stl" "${WORK_DIR}/bad.ply"
           resample "${WORK_DIR}/octahedron.obj" --grid 32 --out "${WORK_DIR}/bad.ply" --mesh "${WORK_DIR}/bad.3mf")
amls_fails("expected .obj, .ply or .stl" "${WORK_DIR}/bad.3mf" deform "${SCENE}" --max-steps 1 --mesh "${WORK_DIR}/bad.3mf")
