// study_text.cpp: see study_text.h.
#include "study/study_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

#include "swarf/core/errors.h"

namespace swarf::study_text {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("cannot read '{}'", path));
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string describe(const std::map<std::string, std::string>& values) {
  std::string out;
  for (const auto& [k, v] : values) out += (out.empty() ? "" : ", ") + k + "=" + v;
  return out;
}

std::string case_id(long long n, int width) { return fmt::format("{:0{}d}", n, width); }
int id_width(long long count) { return std::max<int>(4, int(fmt::format("{}", std::max(0LL, count - 1)).size())); }

std::string log_tail(const std::string& path, int lines) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::vector<std::string> all;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto cr = line.rfind('\r');  // progress lines rewritten in place on a terminal
    all.push_back(cr == std::string::npos ? line : line.substr(cr + 1));
  }
  std::string out;
  for (std::size_t k = all.size() > std::size_t(lines) ? all.size() - lines : 0; k < all.size(); ++k)
    out += all[k] + "\n";
  return out.size() > 2000 ? out.substr(out.size() - 2000) : out;
}

}  // namespace swarf::study_text
