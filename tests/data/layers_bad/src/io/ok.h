// A fixture: io/ may include the engine.
#pragma once
#include "swarf/core/vec3.h"
