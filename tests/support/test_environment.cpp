// What every test program starts with, set before main() and inherited by the facet processes the
// CLI tests start: the cache of preintegrated diffraction tables is off (an empty FACET_CACHE_DIR,
// renderer/diffraction/preintegrated_cache.hpp). A test must neither read tables an earlier run left
// in the user's cache nor fill it with files of up to 260 MiB; the cache's own tests name their folder.
#include <cstdlib>

namespace {

[[maybe_unused]] const bool kTableCacheOff = ::setenv("FACET_CACHE_DIR", "", 1) == 0;

}  // namespace
