# ctest install_tree: installs the build into PREFIX and checks that the installed tree stands on
# its own: the binary runs and names its version and revision, the plotting package, the configs
# and the documents are where `wiggle plot` and a reader look for them, and the man page covers
# every subcommand.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${PREFIX}" RESULT_VARIABLE status
                OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status})")
endif()
execute_process(COMMAND "${PREFIX}/bin/wiggle" --version OUTPUT_VARIABLE version RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT version MATCHES "^wiggle [0-9]+\\.[0-9]+\\.[0-9]+ \\(git [0-9a-z-]+\\)")
  message(FATAL_ERROR "installed wiggle --version: status ${status}, printed '${version}'")
endif()
execute_process(COMMAND "${PREFIX}/bin/wiggle" model --shape disk OUTPUT_VARIABLE model RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT model MATCHES "disk")
  message(FATAL_ERROR "installed wiggle model --shape disk: status ${status}")
endif()
foreach(file share/wiggle/python/wiggleplot/__main__.py share/wiggle/python/wiggleplot/results-schema.json
             share/wiggle/configs/small.toml
             share/wiggle/examples/figures.ipynb share/wiggle/results/paper_depth/fig5/results.csv
             share/wiggle/configs/paper.toml share/doc/wiggle/README.md share/doc/wiggle/docs/CONFIG.md
             share/bash-completion/completions/wiggle share/man/man1/wiggle.1)
  if(NOT EXISTS "${PREFIX}/${file}")
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()
# Every relative link of the installed documents reaches an installed file (anchors aside).
file(GLOB_RECURSE documents "${PREFIX}/share/doc/wiggle/*.md")
foreach(document IN LISTS documents)
  file(READ "${document}" text)
  get_filename_component(folder "${document}" DIRECTORY)
  string(REGEX MATCHALL "\\]\\([^) ]+\\)" links "${text}")
  foreach(link IN LISTS links)
    string(REGEX REPLACE "^\\]\\(([^)#]*).*\\)$" "\\1" target "${link}")
    if(target STREQUAL "" OR target MATCHES "^[a-z]+:")
      continue()
    endif()
    if(NOT EXISTS "${folder}/${target}")
      message(FATAL_ERROR "${document}: the link ${link} reaches nothing installed")
    endif()
  endforeach()
endforeach()
# The man page has a section for every subcommand the installed binary lists.
file(READ "${PREFIX}/share/man/man1/wiggle.1" man)
execute_process(COMMAND "${PREFIX}/bin/wiggle" --help OUTPUT_VARIABLE help)
string(REGEX REPLACE ".*\nSubcommands:\n" "" listing "${help}")
string(REGEX MATCHALL "(^|\n)  [a-z][a-z-]*" commands "${listing}")
list(LENGTH commands count)
if(count LESS 6)
  message(FATAL_ERROR "wiggle --help lists ${count} subcommands")
endif()
foreach(command IN LISTS commands)
  string(STRIP "${command}" command)
  string(FIND "${man}" ".SS wiggle ${command}\n" at)
  if(at LESS 0)
    message(FATAL_ERROR "the man page has no section for wiggle ${command}")
  endif()
endforeach()
file(REMOVE_RECURSE "${PREFIX}")
# The installed package imports without PYTHONPATH from the user site of a ~/.local-like prefix
# (PYTHONUSERBASE is what ~/.local is by default) through wiggle.pth.
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${PREFIX}" OUTPUT_QUIET)
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=PYTHONPATH PYTHONUSERBASE=${PREFIX}
                        /usr/bin/python3 -c "import wiggleplot, os; print(os.path.dirname(wiggleplot.__file__))"
                OUTPUT_VARIABLE imported OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE status ERROR_VARIABLE why)
file(REAL_PATH "${PREFIX}/share/wiggle/python/wiggleplot" expected)
if(EXISTS "${imported}")
  file(REAL_PATH "${imported}" imported)
endif()
file(REMOVE_RECURSE "${PREFIX}")
if(NOT status EQUAL 0 OR NOT imported STREQUAL expected)
  message(FATAL_ERROR "import wiggleplot from the installed prefix: status ${status}, got '${imported}' ${why}")
endif()
# The Debian package recommends every Debian package the plotting package and its analysis API
# import (python/README.md), and ffmpeg for movies.
file(STRINGS "${BUILD}/CPackConfig.cmake" recommends REGEX "CPACK_DEBIAN_PACKAGE_RECOMMENDS")
foreach(package python3-matplotlib python3-numpy python3-pandas ffmpeg)
  if(NOT recommends MATCHES "${package}")
    message(FATAL_ERROR "the .deb does not recommend ${package}: ${recommends}")
  endif()
endforeach()
