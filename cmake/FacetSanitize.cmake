# Sanitizer and fuzzing builds (docs/hardening.md).
#
#   -DFACET_SANITIZE=address,undefined   instrument every facet target (libraries, `facet`, tests,
#                                        benchmarks); a UBSan report aborts (no recovery), so it fails
#                                        the test that triggered it.
#   -DFACET_FUZZ=ON                      (clang only) also compile everything with
#                                        -fsanitize=fuzzer-no-link and build the libFuzzer programs
#                                        under fuzz/; the replay drivers are built in every build.
#
# FACET_SANITIZER_ENV is the environment every test runs with: the suppression files under
# tools/sanitizers/ (third-party frames only, each one explained there) and options that make a
# report fail the test.
set(FACET_SANITIZE "" CACHE STRING "Comma-separated sanitizers (address, undefined, leak, ...)")
option(FACET_FUZZ "Build the libFuzzer targets under fuzz/ (clang only)" OFF)

set(FACET_SANITIZER_DIR ${PROJECT_SOURCE_DIR}/tools/sanitizers)
set(FACET_SANITIZER_ENV
  "ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=0:strict_string_checks=1"
  "LSAN_OPTIONS=suppressions=${FACET_SANITIZER_DIR}/lsan.supp:print_suppressions=0"
  "UBSAN_OPTIONS=suppressions=${FACET_SANITIZER_DIR}/ubsan.supp:print_stacktrace=1:halt_on_error=1")

if(FACET_SANITIZE)
  # Mesa's lavapipe keeps its allocations reachable only from its own globals; the Vulkan loader
  # dlclose()s the driver at vkDestroyInstance, and LeakSanitizer then reports them as leaks from
  # "<unknown module>". Preloading the driver keeps it mapped: with it, no leak is left at all, so
  # no suppression is needed (tools/sanitizers/lsan.supp).
  find_library(FACET_LAVAPIPE_ICD NAMES vulkan_lvp)
  if(FACET_LAVAPIPE_ICD)
    list(APPEND FACET_SANITIZER_ENV "LD_PRELOAD=${FACET_LAVAPIPE_ICD}")
  endif()
  add_compile_options(-fsanitize=${FACET_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=${FACET_SANITIZE})
endif()

if(FACET_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "FACET_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++-16")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
  add_link_options(-fsanitize=fuzzer-no-link)
endif()
