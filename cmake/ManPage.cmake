# Writes the man page wiggle.1 from the program's own help texts, so the page cannot fall behind
# the options: `wiggle --help`, then `wiggle SUBCOMMAND --help` for every subcommand that help
# lists. Run at build time (CMakeLists.txt, target wiggle_man) as
#   cmake -DWIGGLE=path/to/wiggle -DOUT=path/to/wiggle.1 -P cmake/ManPage.cmake

function(help_of out)
  execute_process(COMMAND "${WIGGLE}" ${ARGN} --help OUTPUT_VARIABLE text RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${WIGGLE} ${ARGN} --help failed (${status})")
  endif()
  string(REPLACE "Usage: ${WIGGLE}" "Usage: wiggle" text "${text}")  # the help names the binary's path
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# Help text as roff, kept as it is printed (no fill): backslashes escaped, and a line that starts
# with a dot or an apostrophe (a roff request otherwise) guarded by \&.
function(as_roff out text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} ".nf\n${text}\n.fi\n" PARENT_SCOPE)
endfunction()

help_of(main)
execute_process(COMMAND "${WIGGLE}" --version OUTPUT_VARIABLE version OUTPUT_STRIP_TRAILING_WHITESPACE)
# The subcommands: the indented names under "Subcommands:" in the main help.
string(REGEX REPLACE ".*\nSubcommands:\n" "" listing "${main}")
string(REGEX MATCHALL "(^|\n)  [a-z][a-z-]*" names "${listing}")
set(page ".TH WIGGLE 1 \"\" \"${version}\" \"User Commands\"\n")
string(APPEND page ".SH NAME\nwiggle \\- a horizontally wiggling intruder in a 2D bed of frictional grains\n")
string(APPEND page ".SH SYNOPSIS\n.B wiggle\n\\fISUBCOMMAND\\fR [\\fIOPTIONS\\fR]\n")
as_roff(text "${main}")
string(APPEND page ".SH DESCRIPTION\n${text}")
string(APPEND page ".SH COMMANDS\n")
foreach(name IN LISTS names)
  string(STRIP "${name}" name)
  help_of(sub ${name})
  as_roff(text "${sub}")
  string(APPEND page ".SS wiggle ${name}\n${text}")
endforeach()
string(APPEND page ".SH EXIT STATUS\n0 when everything asked for succeeded; 2 for bad input (a one-line message names it); "
                   "other non-zero values for failures at run time (each subcommand's help says which).\n")
string(APPEND page ".SH FILES\n.TP\n~/.cache/wiggle\nthe bed cache (bed.cache_dir, else $WIGGLE_CACHE)\n"
                   ".TP\nshare/doc/wiggle\nREADME.md and, in docs/, the documents: CONFIG.md (every key), "
                   "OUTPUT-FORMATS.md, SWEEPS.md, PHYSICS.md; in study/, VALIDATION.md (does it reproduce the paper)\n")
string(APPEND page ".SH SEE ALSO\nlmp(1), the LAMMPS molecular dynamics program: wiggle export-lammps writes the same case as a LAMMPS deck.\n")
file(WRITE "${OUT}" "${page}")
