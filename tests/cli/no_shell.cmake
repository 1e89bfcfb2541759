# Scene strings must never reach a shell or an interpreter's eval: external
# tools are started with posix_spawn and a fixed argument list
# (renderer/process/run_process.cpp). This check fails on any new call that
# would go through a shell (system, popen, exec*p with "sh", "/bin/sh") in
# the C++ sources, or through eval/exec/os.system/subprocess in the Blender
# script.
#
# No exception: the report's plot runs gnuplot through runProcess too.
set(_allowed "")
file(GLOB_RECURSE _cpp RELATIVE ${ROOT}
  ${ROOT}/renderer/*.cpp ${ROOT}/renderer/*.h ${ROOT}/exporters/*.cpp ${ROOT}/exporters/*.h)
file(GLOB_RECURSE _py RELATIVE ${ROOT} ${ROOT}/exporters/*.py)
set(_found "")
foreach(_f ${_cpp} ${_py})
  file(STRINGS ${ROOT}/${_f} _lines)
  if(_f MATCHES "\\.py$")
    set(_re "(^|[^a-zA-Z_.])(eval|exec|compile|__import__)\\(|os\\.system|os\\.popen|subprocess|shell=True")
  else()
    set(_re "(^|[^a-zA-Z_])(system|popen|execl|execlp|execvp|execvpe|wordexp)\\(|\"/bin/sh\"|\"sh\"")
  endif()
  foreach(_line IN LISTS _lines)
    if(_line MATCHES "${_re}" AND NOT _line MATCHES "^[ ]*(//|#)")
      string(STRIP "${_line}" _s)
      set(_hit "${_f}:${_s}")
      set(_ok FALSE)
      foreach(_a ${_allowed})
        if(_hit MATCHES "${_a}")
          set(_ok TRUE)
        endif()
      endforeach()
      if(NOT _ok)
        list(APPEND _found "${_hit}")
      endif()
    endif()
  endforeach()
endforeach()
if(_found)
  string(REPLACE ";" "\n  " _found "${_found}")
  message(FATAL_ERROR "calls that would go through a shell or eval:\n  ${_found}")
endif()
list(LENGTH _cpp _n1)
list(LENGTH _py _n2)
message("no shell or eval in ${_n1} C++ files and ${_n2} Python files (1 known exception: report.cpp's gnuplot)")
