// Linked into every executable of a sanitizer build (cmake/FacetSanitize.cmake, docs/hardening.md):
// the sanitizers' options and LeakSanitizer's suppression file are compiled in, so a report fails
// every program the same way, whether ctest, a test's child `facet` process, a fuzz program or a
// user started it.
#include <dlfcn.h>

#ifndef FACET_SANITIZER_DIR
#error "FACET_SANITIZER_DIR must name tools/sanitizers"
#endif

extern "C" {
// halt_on_error: the first report ends the program with a failure (no recovery).
const char* __asan_default_options() {
  return "detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=0:strict_string_checks=1";
}
const char* __lsan_default_options() { return "suppressions=" FACET_SANITIZER_DIR "/lsan.supp:print_suppressions=0"; }
const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }
}

namespace {
// Mesa's lavapipe keeps its allocations reachable only from its own globals, and the Vulkan loader
// unmaps the driver at vkDestroyInstance: LeakSanitizer then reports them as leaks from
// "<unknown module>" (128 bytes per instance). Keeping the driver mapped for the life of the
// process leaves them reachable, so nothing is reported and no suppression is needed. A system
// without lavapipe simply has nothing to pin.
[[maybe_unused]] const bool kLavapipePinned =
    dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE) != nullptr;
}  // namespace
