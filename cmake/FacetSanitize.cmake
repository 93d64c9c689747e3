# Sanitizer and fuzzing builds (docs/hardening.md).
#
#   -DFACET_SANITIZE=address,undefined   instrument every facet target (libraries, `facet`, tests,
#                                        benchmarks); a UBSan report aborts (no recovery), so it fails
#                                        the test that triggered it.
#   -DFACET_FUZZ=ON                      (clang only) also compile everything with
#                                        -fsanitize=fuzzer-no-link and build the libFuzzer programs
#                                        under fuzz/; the replay drivers are built in every build.
#
# In a sanitizer build every executable also gets tools/sanitizers/sanitizer_defaults.cpp
# (facet_sanitize_executable): the options that make a report fail the program, LeakSanitizer's
# suppression file, and lavapipe kept loaded. Third-party UBSan reports are left out at compile
# time (tools/sanitizers/ubsan_ignorelist.txt): a check built without recovery cannot be
# suppressed at run time. Each entry in either file is explained there.
set(FACET_SANITIZE "" CACHE STRING "Comma-separated sanitizers (address, undefined, leak, ...)")
option(FACET_FUZZ "Build the libFuzzer targets under fuzz/ (clang only)" OFF)

if(FACET_SANITIZE)
  # Line tables are enough for the reports' stack traces and cost far less to compile and link than
  # full debug information.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    set(facet_sanitizer_flags -gline-tables-only
        -fsanitize-ignorelist=${PROJECT_SOURCE_DIR}/tools/sanitizers/ubsan_ignorelist.txt)
  else()
    set(facet_sanitizer_flags -g1)
  endif()
  # -O1, not the build type's -O3: the instrumented -O3 build cost CI two thirds of its 15 minutes;
  # -O1 compiles ~20 % faster and still runs the kernels and references the tests check at speed
  # (AddressSanitizer's recommended level). Glue code drops to -O0 (facet_glue_code).
  add_compile_options(-O1 -fsanitize=${FACET_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer
                      ${facet_sanitizer_flags})
  add_link_options(-fsanitize=${FACET_SANITIZE})
  add_library(facet_sanitizer_defaults OBJECT ${PROJECT_SOURCE_DIR}/tools/sanitizers/sanitizer_defaults.cpp)
  target_compile_definitions(facet_sanitizer_defaults PRIVATE
    FACET_SANITIZER_DIR="${PROJECT_SOURCE_DIR}/tools/sanitizers")
endif()

# Code that parses options, writes reports or drives the renderer and runs for milliseconds per
# test (the command line, report, batch, and the tests that exercise them): -O0 in sanitizer builds,
# a third of the compile time of the instrumented -O1/-O3 (23 s -> 7 s for compare_command.cpp).
# A directory calls it before its targets.
macro(facet_glue_code)
  if(FACET_SANITIZE)
    add_compile_options(-O0)
  endif()
endmacro()

# Sources of a glue directory that run the shared kernels inline over many inputs (facet eval, the
# report's stability sweep) stay at -O1.
function(facet_hot_sources)
  if(FACET_SANITIZE)
    set_source_files_properties(${ARGN} DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} PROPERTIES COMPILE_OPTIONS -O1)
  endif()
endfunction()

# Adds the sanitizer defaults to executable `target` (nothing without FACET_SANITIZE).
function(facet_sanitize_executable target)
  if(FACET_SANITIZE)
    target_sources(${target} PRIVATE $<TARGET_OBJECTS:facet_sanitizer_defaults>)
    target_link_libraries(${target} PRIVATE ${CMAKE_DL_LIBS})
  endif()
endfunction()

if(FACET_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "FACET_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++-16")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
  add_link_options(-fsanitize=fuzzer-no-link)
endif()
