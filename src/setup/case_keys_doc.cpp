// case_keys_doc.cpp: markdown key tables and their blocks in docs/case-reference.md (see case_keys_doc.h).
#include "setup/case_keys_doc.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "setup/case_keys.h"
#include "swarf/core/errors.h"

namespace swarf {
namespace {

std::string id_of(const KeyRow& r) { return r.section.empty() ? r.table : r.table + ":" + r.section; }

// A '|' inside a cell would end it.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string row_line(const KeyRow& r) {
  std::string line = "| `" + r.name + "` |";
  for (const std::string& c : {r.type, r.unit.empty() ? std::string("-") : r.unit, r.default_value, r.allowed, r.doc})
    line += c.empty() ? std::string(" |") : fmt::format(" {} |", cell(c));
  return line;
}

// Keys that another table's docs describe (the motion keys of [[mesh]]) share one row.
std::string shared_line(const std::vector<const KeyRow*>& shared) {
  std::string names;
  for (const KeyRow* r : shared) names += (names.empty() ? "`" : ", `") + r->name + "`";
  const std::string& other = shared.front()->shared_with;
  return fmt::format("| {} | | | | as for `[[{}]]` | The keys and checks of `[[{}]]`, for the whole {}. |", names,
                     other, other, shared.front()->table);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::string begin_marker(const std::string& id) { return "<!-- keys:" + id + " begin -->"; }
std::string end_marker(const std::string& id) { return "<!-- keys:" + id + " end -->"; }

// The id of a begin marker line, or empty.
std::string begin_id(const std::string& line) {
  const std::string head = "<!-- keys:", tail = " begin -->";
  if (line.rfind(head, 0) != 0 || line.size() < head.size() + tail.size() ||
      line.compare(line.size() - tail.size(), tail.size(), tail) != 0)
    return "";
  return line.substr(head.size(), line.size() - head.size() - tail.size());
}

// The Restart section's block: the keys a restart may --set (Key::restartable), so that the
// section's list cannot drift from the check in the run (app/run.cpp).
constexpr std::string_view kRestartableBlock = "restartable";

std::string restartable_markdown() {
  std::string out = "| key | unit |\n|---|---|\n";
  for (const auto& r : case_key_rows())
    if (r.restartable) out += fmt::format("| `{}.{}` | {} |\n", r.table, r.name, r.unit.empty() ? "-" : r.unit);
  return out;
}

// Every block id of the document: the key tables, then the restartable keys.
std::vector<std::string> block_ids() {
  std::vector<std::string> ids = key_table_ids();
  ids.emplace_back(kRestartableBlock);
  return ids;
}

std::string block_markdown(std::string_view id) {
  return id == kRestartableBlock ? restartable_markdown() : key_table_markdown(id);
}

struct Block {
  std::string id;
  std::size_t first = 0, last = 0;  // the content lines [first, last) between the markers
};

// The marker blocks of a document; throws std::runtime_error for a malformed or missing one.
std::vector<Block> blocks_of(const std::vector<std::string>& lines) {
  const auto ids = block_ids();
  const std::set<std::string> known(ids.begin(), ids.end());
  std::vector<Block> blocks;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string id = begin_id(lines[i]);
    if (id.empty()) continue;
    if (!known.count(id)) throw std::runtime_error(fmt::format("line {}: unknown key table '{}'", i + 1, id));
    if (!seen.insert(id).second) throw std::runtime_error(fmt::format("line {}: second block of '{}'", i + 1, id));
    std::size_t j = i + 1;
    while (j < lines.size() && lines[j] != end_marker(id)) ++j;
    if (j == lines.size()) throw std::runtime_error(fmt::format("line {}: block '{}' has no end marker", i + 1, id));
    blocks.push_back({id, i + 1, j});
    i = j;
  }
  for (const auto& id : ids)
    if (!seen.count(id))
      throw std::runtime_error(fmt::format("no block for key table '{}' ({})", id, begin_marker(id)));
  return blocks;
}

// The key a table line is about: its first cell, without the backticks.
std::string key_of(const std::string& line) {
  const auto a = line.find('|'), b = line.find('|', a + 1);
  if (a == std::string::npos || b == std::string::npos) return line;
  std::string k = line.substr(a + 1, b - a - 1);
  std::string out;
  for (char c : k)
    if (c != '`') out += c;
  const auto s = out.find_first_not_of(' '), e = out.find_last_not_of(' ');
  return s == std::string::npos ? "" : out.substr(s, e - s + 1);
}

}  // namespace

std::vector<std::string> key_table_ids() {
  std::vector<std::string> ids;
  for (const auto& r : case_key_rows())
    if (ids.empty() || ids.back() != id_of(r)) {
      for (const auto& seen : ids)
        if (seen == id_of(r)) throw std::logic_error("key table '" + seen + "' is not contiguous (case_key_text.cpp)");
      ids.push_back(id_of(r));
    }
  return ids;
}

std::string key_table_markdown(std::string_view id) {
  const auto rows = case_key_rows();
  std::string out = "| key | type | unit | default | allowed | meaning |\n|---|---|---|---|---|---|\n";
  std::vector<const KeyRow*> shared;
  bool found = false;
  for (const auto& r : rows) {
    if (id_of(r) != id) continue;
    found = true;
    if (!r.shared_with.empty()) {
      shared.push_back(&r);
      continue;
    }
    if (!shared.empty()) out += shared_line(shared) + "\n", shared.clear();
    out += row_line(r) + "\n";
  }
  if (!shared.empty()) out += shared_line(shared) + "\n";
  if (!found) throw std::invalid_argument(fmt::format("no key table '{}'", id));
  return out;
}

std::string key_tables_markdown() {
  std::string out;
  for (const auto& id : block_ids()) out += begin_marker(id) + "\n" + block_markdown(id) + end_marker(id) + "\n\n";
  return out;
}

std::string key_list_text() {
  const auto rows = case_key_rows();
  std::size_t w_key = 0, w_type = 0, w_unit = 0;
  for (const auto& r : rows) {
    w_key = std::max(w_key, r.table.size() + 1 + r.name.size());
    w_type = std::max(w_type, r.type.size());
    w_unit = std::max(w_unit, std::max<std::size_t>(r.unit.size(), 1));
  }
  std::string out;
  for (const auto& r : rows)
    out += fmt::format("{:<{}}  {:<{}}  {:<{}}  {}\n", r.table + "." + r.name, w_key, r.type, w_type,
                       r.unit.empty() ? "-" : r.unit, w_unit, r.default_value);
  return out;
}

std::string update_key_tables(const std::string& document) {
  const auto lines = lines_of(document);
  std::string out;
  std::size_t next = 0;
  for (const Block& b : blocks_of(lines)) {
    for (; next < b.first; ++next) out += lines[next] + "\n";
    out += block_markdown(b.id);
    next = b.last;
  }
  for (; next < lines.size(); ++next) out += lines[next] + "\n";
  return out;
}

void update_key_tables_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("'{}' cannot be read", path));
  std::stringstream ss;
  ss << in.rdbuf();
  std::string updated;
  try {
    updated = update_key_tables(ss.str());
  } catch (const std::runtime_error& e) {
    throw InputError(fmt::format("{}: {}", path, e.what()));
  }
  std::ofstream out(path, std::ios::binary);
  if (!(out << updated)) throw InputError(fmt::format("'{}' cannot be written", path));
}

std::string key_tables_difference(const std::string& document) {
  const auto lines = lines_of(document);
  std::vector<Block> blocks;
  try {
    blocks = blocks_of(lines);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  for (const Block& b : blocks) {
    const auto want = lines_of(block_markdown(b.id));
    const std::size_t have = b.last - b.first;
    for (std::size_t k = 0; k < std::max(want.size(), have); ++k) {
      const std::string doc = k < have ? lines[b.first + k] : "(nothing)";
      const std::string gen = k < want.size() ? want[k] : "(nothing)";
      if (doc == gen) continue;
      const std::string doc_key = k < have ? key_of(doc) : "", gen_key = k < want.size() ? key_of(gen) : "";
      const std::string what = doc_key == gen_key || doc_key.empty() || gen_key.empty()
                                   ? fmt::format("key '{}' differs", doc_key.empty() ? gen_key : doc_key)
                                   : fmt::format("the document has key '{}' where the key table has key '{}'", doc_key,
                                                 gen_key);
      return fmt::format(
          "table '{}', line {}: {}\n  document:  {}\n  key table: {}\n"
          "(edit src/setup/case_keys.cpp, then run 'swarf case keys --update docs/case-reference.md')",
          b.id, b.first + k + 1, what, doc, gen);
    }
  }
  return "";
}

}  // namespace swarf
