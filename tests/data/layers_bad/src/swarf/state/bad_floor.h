// A fixture for the 'layers_catches_bad_include' test: a state header that reaches up to the
// integrators (the engine's floors: scripts/check_layers.py). check_layers.py must reject it.
#pragma once
#include "swarf/laws/rotation.h"
