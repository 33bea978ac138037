# Checks shared by the CTest scripts that run the built `amls` (AMLS is its path).

# Runs amls with the arguments after `expected` and `output`; it must fail with
# `expected` in its message and leave no `output` behind.
function(amls_fails expected output)
  execute_process(COMMAND "${AMLS}" ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(code EQUAL 0)
    message(FATAL_ERROR "amls ${ARGN} succeeded but should have failed")
  endif()
  string(FIND "${out}${err}" "${expected}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "amls ${ARGN}: expected '${expected}' in the message, got:\n${out}${err}")
  endif()
  if(EXISTS "${output}")
    message(FATAL_ERROR "amls ${ARGN} failed but left ${output}")
  endif()
endfunction()
