// Study table gathering. See study_table.hpp.
#include "study/study_table.hpp"

#include <algorithm>
#include <cstdio>

#include "core/error.hpp"

namespace plyimpact::study {

double CaseRow::quantity(const std::string& column) const {
  for (const auto& q : quantities)
    if (q.name == column) return q.value;
  return std::nan("");
}

std::string csv_number(double v) {
  if (std::isnan(v)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

StudyTable gather_table(const StudySpec& spec, const std::vector<Case>& cases, const std::filesystem::path& dir,
                        const std::vector<std::string>& failures) {
  StudyTable t;
  for (const auto& p : spec.parameters) t.parameter_keys.push_back(p.key);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    CaseRow row{c.name, "pending", c.values, {}, {}};
    const auto case_dir = dir / c.name;
    if (!failures[i].empty()) {
      row.status = msg() << "failed: " << failures[i] << " (see " << (case_dir / "run.log").string() << ")";
    } else if (case_finished(c, case_dir)) {
      row.status = "finished";
      try {
        RunRecord record = read_run_record(case_dir.string());
        record.pass_distance = c.pass_distance;
        if (const auto* s = record.summary.find("status"); s && s->kind() == output::Json::Kind::string)
          row.status = s->as_string();  // "completed" or "stopped"
        for (const auto& name : spec.quantities) {
          try {
            for (auto& v : find_quantity(name)->compute(record)) row.quantities.push_back(std::move(v));
          } catch (const NotAvailable& e) {
            row.notes.push_back(msg() << name << ": " << e.what());
          }
        }
      } catch (const InputError& e) {
        row.status = std::string("unreadable: ") + e.what();
      }
    }
    for (const auto& q : row.quantities)
      if (std::find(t.quantity_columns.begin(), t.quantity_columns.end(), q.name) == t.quantity_columns.end())
        t.quantity_columns.push_back(q.name);
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string study_csv(const StudyTable& t) {
  auto field = [](const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q(1, '"');
    for (char c : s) {
      if (c == '"') q += '"';
      q += c;
    }
    q += '"';
    return q;
  };
  std::string out = "case,status";
  auto cell = [&out](const std::string& text) {
    out += ',';
    out += text;
  };
  for (const auto& k : t.parameter_keys) cell(field(k));
  for (const auto& q : t.quantity_columns) cell(field(q));
  out += '\n';
  for (const auto& r : t.rows) {
    out += field(r.name);
    cell(field(r.status));
    for (const auto& v : r.values) cell(csv_number(leading_number(v)));
    for (const auto& q : t.quantity_columns) cell(csv_number(r.quantity(q)));
    out += '\n';
  }
  return out;
}

}  // namespace plyimpact::study
