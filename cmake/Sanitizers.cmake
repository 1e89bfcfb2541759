# Build options for robustness testing (docs/robustness.md).
#
# XVAL_SANITIZE=ON: every target is compiled and linked with
# AddressSanitizer and UndefinedBehaviorSanitizer; any undefined behaviour
# aborts the program (-fno-sanitize-recover), so a test that hits it fails.
# The system libraries (Embree, OpenImageIO, ...) are not instrumented: bugs
# inside them are not seen, but our code's use of their memory is.
#
# XVAL_FUZZ=ON: also builds the libFuzzer targets in tests/fuzz (needs
# clang and libclang-rt-dev; implies nothing about XVAL_SANITIZE, but they
# are meant to be used together).
option(XVAL_SANITIZE "Build everything with -fsanitize=address,undefined" OFF)
option(XVAL_FUZZ "Build the libFuzzer targets (tests/fuzz; clang only)" OFF)

if(XVAL_SANITIZE)
  set(XVAL_SANITIZER_FLAGS
    -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_compile_options(${XVAL_SANITIZER_FLAGS})
  add_link_options(${XVAL_SANITIZER_FLAGS})
  message(STATUS "xval: sanitizers on (${XVAL_SANITIZER_FLAGS})")
endif()

if(XVAL_FUZZ AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "XVAL_FUZZ=ON needs clang (libFuzzer): configure with "
                      "-DCMAKE_CXX_COMPILER=clang++")
endif()
