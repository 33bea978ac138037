# `--resample` end to end (run by CTest as a script):
#   cmake -DAMLS=<amls> -DSCENE=<clover2d.json> -DWORK_DIR=<dir> -P resample_option_test.cmake
# A short `amls deform` under `auto` reports its policy and resamples, per step
# too; bad values and --no-resample with --resample fail before any work,
# naming the option. A small vortex under `auto` prints and records the time
# of its quality checks.
include("${CMAKE_CURRENT_LIST_DIR}/amls_command_checks.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# Runs amls deform with `args`; it must fail with `expected` in its message and write no report.
function(deform_fails expected)
  amls_fails("${expected}" "${WORK_DIR}/bad.json" deform "${SCENE}" ${ARGN} --json "${WORK_DIR}/bad.json")
endfunction()

# Fails unless `actual` equals `expected`.
function(expect what actual expected)
  if(NOT "${actual}" STREQUAL "${expected}")
    message(FATAL_ERROR "${what}: expected '${expected}', got '${actual}'")
  endif()
endfunction()

# Fails unless `text` holds `part`.
function(expect_in what text part)
  string(FIND "${text}" "${part}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "${what}: expected '${part}' in:\n${text}")
  endif()
endfunction()

set(report "${WORK_DIR}/auto.json")
execute_process(COMMAND "${AMLS}" deform "${SCENE}" --resample auto --max-steps 12 --tracers 2 --json "${report}"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "amls deform --resample auto failed (${code}):\n${out}${err}")
endif()
expect_in("the printed report (policy and resamples)" "${out}" "resample auto: ")
expect_in("the printed report (time of the quality checks)" "${out}" "sampling-quality checks (auto): ")
file(READ "${report}" json)
string(JSON policy GET "${json}" resample)
string(JSON status GET "${json}" status)
string(JSON steps GET "${json}" steps)
string(JSON resamples GET "${json}" resamples)
string(JSON frames GET "${json}" spacing_frames)
string(JSON records LENGTH "${json}" per_step)
string(JSON first GET "${json}" per_step 0 resampled)
expect("resample" "${policy}" "auto")
expect("status" "${status}" "ok")
expect("steps" "${steps}" "12")
expect("per_step records" "${records}" "13")
expect("step 0 resampled" "${first}" "ON")
expect("spacing frames (those right after a resample)" "${frames}" "${resamples}")
if(resamples LESS 1 OR resamples GREATER_EQUAL steps)
  message(FATAL_ERROR "auto did ${resamples} resamples in ${steps} steps: expected at least 1 and fewer than the steps")
endif()
set(counted 0)
math(EXPR last "${records} - 1")
foreach(i RANGE ${last})
  string(JSON resampled GET "${json}" per_step ${i} resampled)
  if(resampled)
    math(EXPR counted "${counted} + 1")
  endif()
endforeach()
expect("records that say they resampled" "${counted}" "${resamples}")

execute_process(COMMAND "${AMLS}" vortex --grid 32 --resample auto --json "${WORK_DIR}/vortex.json"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "amls vortex --resample auto failed (${code}):\n${out}${err}")
endif()
expect_in("amls vortex --resample auto" "${out}" "sampling-quality checks (auto, outside the phases): ")
file(READ "${WORK_DIR}/vortex.json" json)
string(JSON quality GET "${json}" quality_seconds)
if(NOT quality GREATER 0)
  message(FATAL_ERROR "the vortex report's quality_seconds is ${quality}, expected the time of its checks")
endif()

deform_fails("--resample must be always, auto, local or every:K" --resample sometimes --max-steps 1)
deform_fails("--resample must be always, auto, local or every:K" --resample every:0 --max-steps 1)
deform_fails("--resample must be always, auto, local or every:K" --resample every:2x --max-steps 1)
deform_fails("--resample excludes --no-resample" --no-resample --resample auto --max-steps 1)
message(STATUS "--resample: auto reports its resamples and the time of its checks; bad values fail clearly")
