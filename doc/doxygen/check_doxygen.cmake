# The test doc/doxygen (doc/doxygen/CMakeLists.txt): run Doxygen on include/perideal and fail
# if it warns. Arguments: DOXYGEN (the executable, empty if not found), DOXYFILE, WARNINGS (the
# WARN_LOGFILE of the Doxyfile).
if(NOT DOXYGEN)
  message(FATAL_ERROR "Doxygen is not installed, so the library reference cannot be checked: "
    "apt-get install doxygen (contrib/install_dependencies.sh), then configure again.")
endif()
file(REMOVE ${WARNINGS})
execute_process(COMMAND ${DOXYGEN} ${DOXYFILE} RESULT_VARIABLE _result)
if(NOT _result EQUAL 0)
  message(FATAL_ERROR "Doxygen failed (exit code ${_result}).")
endif()
file(READ ${WARNINGS} _warnings)
if(NOT _warnings STREQUAL "")
  message(FATAL_ERROR "Doxygen warns about the comments in include/perideal; document every "
    "public class, member and function, and name only existing parameters in @param:\n"
    "${_warnings}")
endif()
message(STATUS "Doxygen: no warnings")
