// Case expansion, naming and completion records. See cases.hpp.
#include "study/cases.hpp"

#include <cctype>
#include <cstdint>
#include <cstdio>

#include "core/error.hpp"
#include "output/json.hpp"
#include "output/json_reader.hpp"

namespace plyimpact::study {
namespace {

namespace fs = std::filesystem;

// "contacts[0].SOFT" -> "SOFT", "impactor.velocity" -> "velocity".
std::string short_key(const std::string& key) {
  std::string k = key.substr(key.find_last_of('.') == std::string::npos ? 0 : key.find_last_of('.') + 1);
  std::string out;
  for (char c : k)
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') out += c;
  return out.empty() ? "p" : out;
}

// A value as a folder-name fragment: "5 m/s" -> "5m_s", "-1.5e-3" -> "-1.5e-3".
std::string file_safe(const std::string& value) {
  std::string out;
  for (char c : value) {
    if (c == ' ') continue;
    out += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+') ? c : '_';
  }
  return out.empty() ? "_" : out;
}

std::vector<std::vector<std::size_t>> combinations(const StudySpec& spec) {
  std::vector<std::vector<std::size_t>> out;
  const std::size_t np = spec.parameters.size();
  if (spec.combine == Combine::zip) {
    for (std::size_t i = 0; i < spec.parameters.front().values.size(); ++i) out.emplace_back(np, i);
    return out;
  }
  std::vector<std::size_t> idx(np, 0);
  for (;;) {
    out.push_back(idx);
    std::size_t p = np;
    while (p > 0) {
      --p;
      if (++idx[p] < spec.parameters[p].values.size()) break;
      idx[p] = 0;
      if (p == 0) return out;
    }
  }
}

}  // namespace

std::string fnv1a_hex(std::string_view text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

Case make_case(const StudySpec& spec, const std::string& scene_text, const std::vector<ParameterValue>& values) {
  Case c;
  c.overrides = spec.fixed;
  std::string name;
  for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
    const Parameter& par = spec.parameters[p];
    const ParameterValue& v = values.at(p);
    c.values.push_back(v.text);
    c.overrides.push_back({par.key, v.text, v.origin + ": " + par.key + "=" + v.text});
    if (!name.empty()) name += '_';
    name += short_key(par.key);
    name += '-';
    name += file_safe(v.text);
  }
  std::string identity = scene_text;
  identity += '\0';
  for (const auto& o : c.overrides) identity += o.key_path + "=" + o.value + '\0';
  identity += PLYIMPACT_VERSION;
  c.hash = fnv1a_hex(identity);
  c.name = name + "_" + c.hash.substr(0, 8);
  return c;
}

std::vector<Case> expand_cases(const StudySpec& spec, const std::string& scene_text) {
  std::vector<Case> cases;
  for (const auto& p : spec.parameters)
    if (p.values.empty()) return cases;
  for (const auto& idx : combinations(spec)) {
    std::vector<ParameterValue> values;
    for (std::size_t p = 0; p < spec.parameters.size(); ++p) values.push_back(spec.parameters[p].values[idx[p]]);
    cases.push_back(make_case(spec, scene_text, values));
  }
  return cases;
}

bool case_finished(const Case& c, const fs::path& dir) {
  if (!fs::exists(dir / "case.json") || !fs::exists(dir / "summary.json") || !fs::exists(dir / "history.csv"))
    return false;
  try {
    const output::Json record = output::read_json_file(dir / "case.json");
    const output::Json* h = record.find("hash");
    if (!h || h->kind() != output::Json::Kind::string || h->as_string() != c.hash) return false;
    // A run stopped by a signal (the study or the machine interrupted) is not a result: run it again.
    const output::Json summary = output::read_json_file(dir / "summary.json");
    const output::Json* status = summary.find("status");
    return !(status && status->kind() == output::Json::Kind::string && status->as_string() == "interrupted");
  } catch (const InputError&) {
    return false;  // an unreadable record: run the case again
  }
}

void write_case_record(const StudySpec& spec, const Case& c, const fs::path& dir, const std::string& status) {
  output::Json j = output::Json::object();
  j["study"] = spec.file.string();
  j["case"] = c.name;
  j["hash"] = c.hash;
  j["version"] = PLYIMPACT_VERSION;
  j["scene"] = fs::absolute(spec.scene).string();
  output::Json params = output::Json::object();
  for (std::size_t p = 0; p < spec.parameters.size(); ++p) params[spec.parameters[p].key] = c.values[p];
  j["parameters"] = params;
  output::Json overrides = output::Json::array();
  for (const auto& o : c.overrides) overrides.push_back(o.key_path + "=" + o.value);
  j["overrides"] = overrides;
  j["status"] = status;
  fs::create_directories(dir);
  output::write_json_atomically(dir / "case.json", j);
}

std::vector<std::string> case_arguments(const StudySpec& spec, const Case& c, const fs::path& dir, int threads) {
  std::vector<std::string> args = {"run", fs::absolute(spec.scene).string()};
  for (const auto& o : c.overrides) {
    args.push_back("--set");
    args.push_back(o.key_path + "=" + o.value);
  }
  args.push_back("--threads");
  args.push_back(std::to_string(threads));
  args.push_back("-o");
  args.push_back(fs::absolute(dir).string());
  return args;
}

}  // namespace plyimpact::study
