// A fixture for the 'layers_catches_bad_include' test: an engine header that includes a
// file format and a library the engine may not use. check_layers.py must reject it.
#pragma once
#include <toml++/toml.h>
#include "io/h5file.h"
