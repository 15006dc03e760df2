// memory_archive.h: the engine's in-memory state archive (swarf/core/memory_archive.h) under the
// name the restart tests use.
#pragma once

#include "swarf/core/memory_archive.h"

namespace swarf::test {

using MemoryArchive = swarf::MemoryArchive;

}  // namespace swarf::test
