// tool_spec.h: the generated tool of the tool tests (test_tool.cpp, test_tool_file.cpp): 4 mm
// wide, faces 2 mm long, with the given angles and edge radius.
#pragma once

#include "tool_paths/tool_geometry.h"

namespace swarf::test {

inline ToolSpec tool_spec(double rake, double clearance, double radius) {
  ToolSpec s;
  s.rake_angle_deg = rake;
  s.clearance_angle_deg = clearance;
  s.edge_radius = radius;
  s.width = 4e-3;
  s.face_length = 2e-3;
  return s;
}

}  // namespace swarf::test
