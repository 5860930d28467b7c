// The study table: one row per case (name, status, parameter values, quantity values), gathered
// from the case folders, and its CSV form (study.csv). Parameter columns hold the numeric part of
// each value ("5 m/s" -> 5; the text is in study.json); a quantity a case cannot provide, or a
// case not finished, leaves its cell empty (gnuplot and pandas read an empty cell as missing).
#pragma once

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "study/cases.hpp"
#include "study/quantities.hpp"
#include "study/study_spec.hpp"

namespace plyimpact::study {

struct CaseRow {
  std::string name;
  std::string status;               // "finished", "pending", "failed: ..."
  std::vector<std::string> values;  // parameter value texts
  std::vector<QuantityValue> quantities;
  std::vector<std::string> notes;   // "<quantity>: <why it is not available>"

  /// Value of the named quantity column, NaN when absent.
  double quantity(const std::string& column) const;
};

struct StudyTable {
  std::vector<std::string> parameter_keys;
  std::vector<std::string> quantity_columns;  // expanded names, in order of first appearance
  std::vector<CaseRow> rows;
};

/// Reads every finished case folder under `dir` and evaluates the study's quantities;
/// `failures[i]` (empty or a reason) marks case i as failed in this invocation.
StudyTable gather_table(const StudySpec& spec, const std::vector<Case>& cases, const std::filesystem::path& dir,
                        const std::vector<std::string>& failures);

/// study.csv text: case, status, parameter columns, quantity columns.
std::string study_csv(const StudyTable& table);

/// "%.10g", or "" for NaN.
std::string csv_number(double v);

}  // namespace plyimpact::study
