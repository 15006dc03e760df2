// study_record.cpp: a study's record in its output folder (study.json, reconciling an earlier
// run's cases, each case's state from its summary) (see study_record.h).
#include "study/study_record.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spawn.h>
#include <sys/wait.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "io/atomic_file.h"
#include "setup/case_config.h"
#include "study/study_table.h"
#include "study/study_text.h"
#include "study/sweep_mpi.h"
#include "swarf/core/errors.h"

namespace swarf {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace study_text;

// ---- study.json -------------------------------------------------------------------------

void write_study_json(const Study& s, const std::string& out_dir) {
  json j;
  j["format"] = "swarf-study-1";
  j["study_file"] = s.file;
  j["title"] = s.title;
  j["base"] = s.base;
  j["base_path"] = s.base_path;
  j["base_hash"] = s.base_hash;
  j["set"] = s.fixed;
  j["parameters"] = s.parameters;
  j["units"] = s.units;
  j["repetitions"] = s.repetitions;
  j["seed_key"] = s.seed_key;
  j["seed_start"] = s.seed_start;
  j["plots"] = s.plots;
  j["plot_metrics"] = s.plot_metrics;
  j["plot_against"] = s.plot_against;
  j["cases"] = json::array();
  for (const auto& c : s.cases)
    j["cases"].push_back({{"id", c.id}, {"values", c.values}, {"repetition", c.repetition}});
  fs::create_directories(out_dir);
  write_text_atomic((fs::path(out_dir) / "study.json").string(), j.dump(2) + "\n");
}

Study read_study_json(const std::string& out_dir) {
  const std::string path = (fs::path(out_dir) / "study.json").string();
  if (!fs::exists(path))
    throw InputError(fmt::format("'{}' is not a study directory: no study.json (written by swarf sweep)", out_dir));
  try {
    const json j = json::parse(read_text(path));
    if (j.at("format") != "swarf-study-1") throw InputError("unknown format " + j.at("format").dump());
    Study s;
    s.file = j.at("study_file");
    s.title = j.at("title");
    s.base = j.at("base");
    s.base_path = j.at("base_path");
    s.base_hash = j.at("base_hash");
    s.fixed = j.at("set").get<std::map<std::string, std::string>>();
    s.parameters = j.at("parameters").get<std::vector<std::string>>();
    s.units = j.at("units").get<std::map<std::string, std::string>>();
    s.repetitions = j.at("repetitions");
    s.seed_key = j.at("seed_key");
    s.seed_start = j.at("seed_start");
    s.plots = j.at("plots");
    s.plot_metrics = j.at("plot_metrics").get<std::vector<std::string>>();
    s.plot_against = j.at("plot_against").get<std::vector<std::string>>();
    for (const auto& c : j.at("cases")) {
      StudyCase sc;
      sc.id = c.at("id");
      sc.values = c.at("values").get<std::map<std::string, std::string>>();
      sc.repetition = c.at("repetition");
      s.cases.push_back(std::move(sc));
    }
    return s;
  } catch (const std::exception& e) {
    throw InputError(fmt::format("'{}' is damaged ({}); remove it to start the study afresh", path, e.what()));
  }
}

void reconcile_study(Study& s, const std::string& out_dir) {
  if (!fs::exists(fs::path(out_dir) / "study.json")) return;
  const Study old = read_study_json(out_dir);
  std::set<std::string> finished;
  for (const auto& c : old.cases)
    if (case_status(old, c, out_dir).state == CaseState::completed) finished.insert(c.id);

  std::vector<std::string> changes;
  if (old.base_hash != s.base_hash)
    changes.push_back(fmt::format("base (the text of the base case '{}' changed)", s.base_path));
  std::set<std::string> fixed_keys;
  for (const auto& [k, v] : old.fixed) fixed_keys.insert(k);
  for (const auto& [k, v] : s.fixed) fixed_keys.insert(k);
  for (const auto& k : fixed_keys) {
    const auto a = old.fixed.find(k);
    const auto b = s.fixed.find(k);
    const std::string va = a == old.fixed.end() ? "not set" : a->second,
                      vb = b == s.fixed.end() ? "not set" : b->second;
    if (va != vb) changes.push_back(fmt::format("set.{} ({} -> {})", k, va, vb));
  }
  if (old.seed_key != s.seed_key)
    changes.push_back(fmt::format("seed_key (\"{}\" -> \"{}\")", old.seed_key, s.seed_key));

  // Match the cases by their values; known cases keep their ids.
  std::map<std::map<std::string, std::string>, std::string> old_ids;
  long long next = 0;
  int width = 4;
  for (const auto& c : old.cases) {
    old_ids[c.values] = c.id;
    next = std::max(next, std::stoll(c.id) + 1);
    width = std::max<int>(width, int(c.id.size()));
  }
  std::set<std::map<std::string, std::string>> fresh;
  for (const auto& c : s.cases) fresh.insert(c.values);
  std::set<std::string> removed_reasons;
  for (const auto& c : old.cases) {
    if (fresh.count(c.values) || !finished.count(c.id)) continue;
    std::string why;
    for (const auto& [k, v] : c.values) {
      // (init-captures: clang 14 cannot capture structured bindings)
      const bool present = std::any_of(s.cases.begin(), s.cases.end(), [&key = k, &value = v](const StudyCase& n) {
        auto it = n.values.find(key);
        return it != n.values.end() && it->second == value;
      });
      if (!present) why += (why.empty() ? "" : ", ") + fmt::format("{} = {} is no longer in the study", k, v);
    }
    for (const auto& k : s.parameters)
      if (!c.values.count(k)) why += (why.empty() ? "" : ", ") + fmt::format("{} is newly varied", k);
    if (why.empty()) why = fmt::format("the point {} is no longer in the study", describe(c.values));
    removed_reasons.insert(fmt::format("{} (finished case {})", why, c.id));
  }
  changes.insert(changes.end(), removed_reasons.begin(), removed_reasons.end());
  if (!changes.empty() && !finished.empty())
    throw InputError(fmt::format(
        "{}: the study changed since {} finished case(s) in '{}' were run: {}. Restore the study file, or run it "
        "with another --out directory (adding values or points is allowed)",
        s.file, finished.size(), out_dir, fmt::join(changes, "; ")));

  for (auto& c : s.cases) {
    auto it = old_ids.find(c.values);
    c.id = it != old_ids.end() ? it->second : case_id(next++, width);
  }
  std::sort(s.cases.begin(), s.cases.end(),
            [](const StudyCase& a, const StudyCase& b) { return std::stoll(a.id) < std::stoll(b.id); });
}

// ---- case state ------------------------------------------------------------------------

std::string CaseStatus::text() const {
  switch (state) {
    case CaseState::completed:
      return "completed";
    case CaseState::failed:
      return exit_code > 128 ? fmt::format("failed (signal {})", exit_code - 128)
                             : fmt::format("failed (exit {})", exit_code);
    case CaseState::interrupted:
      return "interrupted";
    case CaseState::not_run:
      break;
  }
  return "not run";
}

std::string case_dir(const std::string& out_dir, const StudyCase& c) {
  return (fs::path(out_dir) / "cases" / c.id).string();
}

CaseStatus case_status(const Study& study, const StudyCase& c, const std::string& out_dir) {
  const fs::path dir = case_dir(out_dir, c);
  CaseStatus st;
  if (fs::exists(dir / "summary.json")) {
    try {
      const json j = json::parse(read_text((dir / "summary.json").string()));
      if (j.value("status", "") == "completed" &&
          j.value("overrides", std::vector<std::string>{}) == case_overrides(study, c)) {
        st.state = CaseState::completed;
        return st;
      }
    } catch (const std::exception&) {
      // not a complete summary: run the case again
    }
  }
  if (fs::exists(dir / "sweep_status.json")) {
    try {
      const json j = json::parse(read_text((dir / "sweep_status.json").string()));
      st.state = CaseState::failed;
      st.exit_code = j.at("exit_code");
      st.log_tail = j.at("log_tail");
      return st;
    } catch (const std::exception&) {
    }
  }
  st.state = fs::exists(dir / "log.txt") ? CaseState::interrupted : CaseState::not_run;
  return st;
}

}  // namespace swarf
