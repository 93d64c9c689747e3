// Forwards to scene/grating/gsf_file.hpp, where gratings moved (they are scene data), for the fuzz
// targets that still include it here; remove once fuzz/ includes the new path.
#pragma once

#include "scene/grating/gsf_file.hpp"
