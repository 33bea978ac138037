# `amls render` end to end (run by CTest as a script):
#   cmake -DAMLS=<amls> -DSCENE=<clover2d.json> -DWORK_DIR=<dir> -P render_command_test.cmake
# Renders a small generated point set and a scene, checks each PNG's signature and
# IHDR size, and checks that bad input fails with a clear message and no PNG.
include("${CMAKE_CURRENT_LIST_DIR}/amls_command_checks.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# The PNG at `png` exists, is a PNG, and is `width` x `height`.
function(check_png png width height)
  if(NOT EXISTS "${png}")
    message(FATAL_ERROR "${png} was not written")
  endif()
  file(READ "${png}" signature LIMIT 8 HEX)
  if(NOT signature STREQUAL "89504e470d0a1a0a")
    message(FATAL_ERROR "${png} is not a PNG (signature ${signature})")
  endif()
  file(READ "${png}" ihdr OFFSET 12 LIMIT 4 HEX)
  if(NOT ihdr STREQUAL "49484452")  # IHDR
    message(FATAL_ERROR "${png}: no IHDR chunk first")
  endif()
  file(READ "${png}" w OFFSET 16 LIMIT 4 HEX)
  file(READ "${png}" h OFFSET 20 LIMIT 4 HEX)
  math(EXPR w "0x${w}")
  math(EXPR h "0x${h}")
  if(NOT w EQUAL width OR NOT h EQUAL height)
    message(FATAL_ERROR "${png} is ${w}x${h}, expected ${width}x${height}")
  endif()
endfunction()

# Runs amls with `args`; it must succeed.
function(render_ok)
  execute_process(COMMAND "${AMLS}" render ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "amls render ${ARGN} failed (${code}):\n${out}${err}")
  endif()
endfunction()

# Runs amls render with `args`; it must fail with `expected` in its message and write no PNG.
function(render_fails expected png)
  amls_fails("${expected}" "${png}" render ${ARGN} --out "${png}")
endfunction()

# An octahedron's six vertices with outward normals: a tiny 3D point set.
file(WRITE "${WORK_DIR}/octahedron.xyz"
  "1 0 0 1 0 0\n-1 0 0 -1 0 0\n0 1 0 0 1 0\n0 -1 0 0 -1 0\n0 0 1 0 0 1\n0 0 -1 0 0 -1\n")
render_ok("${WORK_DIR}/octahedron.xyz" --out "${WORK_DIR}/octahedron.png" --size 64x48 --normals --color normal
          --view 10,20)
check_png("${WORK_DIR}/octahedron.png" 64 48)

# A scene's initial state (one resampling of 250 points), with the MLS curve and quality colours.
render_ok("${SCENE}" --step 0 --out "${WORK_DIR}/clover.png" --size 100x80 --color quality)
check_png("${WORK_DIR}/clover.png" 100 80)

file(WRITE "${WORK_DIR}/empty.xyz" "# no points\n")
file(WRITE "${WORK_DIR}/nan.xyz" "0 0 0 0 0 1\n1 0 0 nan 0 1\n0 1 0 0 0 1\n")
render_fails("no points" "${WORK_DIR}/bad.png" "${WORK_DIR}/empty.xyz")
render_fails("normal" "${WORK_DIR}/bad.png" "${WORK_DIR}/nan.xyz")
render_fails("--size" "${WORK_DIR}/bad.png" "${WORK_DIR}/octahedron.xyz" --size 0x10)
render_fails("--color" "${WORK_DIR}/bad.png" "${WORK_DIR}/octahedron.xyz" --color rainbow)
render_fails("--view" "${WORK_DIR}/bad.png" "${WORK_DIR}/octahedron.xyz" --view 30,95)
render_fails("--step" "${WORK_DIR}/bad.png" "${SCENE}" --step 100000)
render_fails("--step" "${WORK_DIR}/bad.png" "${WORK_DIR}/octahedron.xyz" --step 2)

# --verbose names the headless OpenGL that drew the image (docs/headless-rendering.md).
execute_process(COMMAND "${AMLS}" render "${WORK_DIR}/octahedron.xyz" --out "${WORK_DIR}/verbose.png" --size 32x24
                        --verbose
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "OpenGL: (egl-device|egl-surfaceless|osmesa)[^\n]*; OpenGL [34]\\.[0-9]")
  message(FATAL_ERROR "amls render --verbose did not name the OpenGL backend and version (${code}):\n${out}${err}")
endif()
check_png("${WORK_DIR}/verbose.png" 32 24)
# The backend options and variables are checked before any work; options replace the variables whole.
render_fails("--gl-backend: 'vulkan' is not a headless OpenGL backend" "${WORK_DIR}/bad.png"
             "${WORK_DIR}/octahedron.xyz" --gl-backend vulkan)
render_fails("--egl-device: 'first' is not an EGL device index" "${WORK_DIR}/bad.png" "${WORK_DIR}/octahedron.xyz"
             --egl-device first)
set(ENV{AMLS_GL_BACKEND} bogus)
render_fails("AMLS_GL_BACKEND: 'bogus'" "${WORK_DIR}/bad.png" "${WORK_DIR}/octahedron.xyz")
render_ok("${WORK_DIR}/octahedron.xyz" --out "${WORK_DIR}/auto.png" --size 16x16 --gl-backend auto)
unset(ENV{AMLS_GL_BACKEND})
check_png("${WORK_DIR}/auto.png" 16 16)
message(STATUS "amls render: PNGs of the asked size; the OpenGL used is named; bad input fails clearly")
