# Write (MODE=write) or check (MODE=check) the parameter reference REFERENCE of dimension
# DIMENSION against `EXECUTABLE --print-parameter-reference DIMENSION`
# (doc/parameters/CMakeLists.txt).
execute_process(COMMAND ${EXECUTABLE} --print-parameter-reference ${DIMENSION}
  OUTPUT_VARIABLE _generated
  RESULT_VARIABLE _result)
if(NOT _result EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --print-parameter-reference ${DIMENSION} failed "
    "(exit code ${_result}).")
endif()
if(MODE STREQUAL "write")
  file(WRITE ${REFERENCE} "${_generated}")
  return()
endif()
file(READ ${REFERENCE} _committed)
if(NOT _generated STREQUAL _committed)
  get_filename_component(_name ${REFERENCE} NAME)
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/${_name} "${_generated}")
  message(FATAL_ERROR "doc/parameters/${_name} differs from the entries the code declares "
    "(what the code prints is in ${CMAKE_CURRENT_BINARY_DIR}/${_name}). After changing a "
    "parameter, regenerate the reference with\n"
    "  cmake --build build --target parameter_reference\n"
    "and commit doc/parameters/.")
endif()
