# ctest archive_revision: a tree made by `git archive` (a release tarball) knows the revision it was
# made from (cmake/GitRevision.cmake reads cmake/ArchiveRevision.txt, filled in by export-subst).
# Archives HEAD of the source checkout SRC into WORK, unpacks it and generates the revision file
# from it. Outside a git checkout (itself built from a tarball) there is no HEAD to archive: skipped.
execute_process(COMMAND git -C "${SRC}" rev-parse --short=12 HEAD OUTPUT_VARIABLE head
                OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message("archive_revision: SKIP: ${SRC} is not a git checkout")
  return()
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/tree")
execute_process(COMMAND git -C "${SRC}" archive --format=tar -o "${WORK}/wiggle.tar" HEAD RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "git archive failed (${status})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E tar xf "${WORK}/wiggle.tar" WORKING_DIRECTORY "${WORK}/tree")
execute_process(COMMAND ${CMAKE_COMMAND} -DSRC=${WORK}/tree -DOUT=${WORK}/GitRevision.cpp
                        -P "${WORK}/tree/cmake/GitRevision.cmake" RESULT_VARIABLE status)
file(READ "${WORK}/GitRevision.cpp" generated)
file(REMOVE_RECURSE "${WORK}")
if(NOT generated MATCHES "return \"${head}\";")
  message(FATAL_ERROR "a git archive of HEAD (${head}) builds as: ${generated}")
endif()
message("archive_revision: ok: the archive of HEAD says ${head}")
