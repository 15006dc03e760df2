// csv_cell.h: one number of a CSV cell, read strictly: the whole cell (spaces around it and a
// '\r' at the end of the line aside) must be the number, so that "3abc", "" or "1..2" are
// refused instead of read as 3 or 0 (strtod with no end check, atof and stream extraction all
// stop at the first character they cannot use).
#pragma once

#include <cstdlib>
#include <string>
#include <string_view>

namespace swarf {

/// Parses 'cell' as a number into 'v' ("nan" and "inf" included: a series may hold them);
/// false when the cell is empty or anything but the number is in it.
inline bool parse_csv_number(std::string_view cell, double& v) {
  while (!cell.empty() && (cell.front() == ' ' || cell.front() == '\t')) cell.remove_prefix(1);
  while (!cell.empty() && (cell.back() == ' ' || cell.back() == '\t' || cell.back() == '\r')) cell.remove_suffix(1);
  if (cell.empty()) return false;
  const std::string s(cell);
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

}  // namespace swarf
