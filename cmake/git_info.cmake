# git_info.cmake: writes OUTPUT (a header) with the source tree's git commit and whether the
# tree differs from it. Run at every build (a custom target in src/app/CMakeLists.txt), so the
# provenance a run records follows the commit that was built, not the one that was configured;
# the file is rewritten only when its text changes, so an unchanged tree recompiles nothing.
execute_process(COMMAND git -C "${SOURCE_DIR}" rev-parse HEAD
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc ERROR_QUIET)
if(NOT rc EQUAL 0)
  set(commit "unknown")  # (a source tarball without .git)
  set(dirty -1)
else()
  # Tracked files only: build directories and run outputs inside the tree do not count.
  execute_process(COMMAND git -C "${SOURCE_DIR}" status --porcelain --untracked-files=no
                  OUTPUT_VARIABLE changes RESULT_VARIABLE rc ERROR_QUIET)
  if(changes STREQUAL "")
    set(dirty 0)
  else()
    set(dirty 1)
  endif()
endif()
set(text "// git_info.h (generated at build time by cmake/git_info.cmake)\n#pragma once\n#define SWARF_GIT_COMMIT \"${commit}\"\n#define SWARF_GIT_DIRTY ${dirty}  // 1 changed tracked files, 0 clean, -1 not a git tree\n")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()
