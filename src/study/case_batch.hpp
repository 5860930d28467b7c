// Runs a batch of study cases side by side as child processes (case_runner.hpp) and keeps each
// case's completion record (case.json) in step: "running" before, then "completed", "stopped"
// (exit 2 with its summary: a result too) or "failed: <why>". Used for a study's listed cases
// and for each round of a ballistic-limit search.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "study/cases.hpp"
#include "study/study_spec.hpp"

namespace plyimpact::study {

struct CaseBatch {
  const StudySpec* spec = nullptr;
  std::filesystem::path dir;      // the study's folder; case i runs in dir / cases[i].name
  std::filesystem::path program;  // the plyimpact executable
  int jobs = 1, threads = 1;
};

/// Runs every case; returns per case "" (a result) or why it failed.
std::vector<std::string> run_case_batch(const CaseBatch& batch, const std::vector<Case>& cases, std::ostream& out);

}  // namespace plyimpact::study
