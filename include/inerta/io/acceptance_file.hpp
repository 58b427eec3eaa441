#pragma once
// Acceptance-criteria files (docs/contact-quality.md "Acceptance"): a small YAML file, or a preset
// shipped in criteria/ (en50367-ac, en50367-ac15, en50367-dc1.5, en50367-dc3), read into analysis::AcceptanceCriteria.
#include <string>
#include <vector>

#include "inerta/analysis/acceptance.hpp"

namespace inerta::io {

/// The presets shipped in criteria/ (their names, sorted).
std::vector<std::string> acceptance_presets();

/// A preset name (letters, digits, '-', '_', '.' not first: no '/' and no .yaml/.yml ending) or a file path.
/// ModelError "file:line: 'key': …; expected …" for an unknown preset (listing the presets), a
/// missing, unknown or non-finite field, a band whose lower edge exceeds its upper one at a speed of
/// its range, a target outside a band where both hold, a bad range, statistics, measure, source or
/// assumed value.
analysis::AcceptanceCriteria load_acceptance(const std::string& preset_or_file);

/// A verdict table as CSV: v_kmh, v_ms, pantograph, criterion, unit, value, limit, margin, status
/// (PASS, FAIL or "not assessed"), note. Numbers with 6 significant digits (as the sweep CSV).
std::string acceptance_csv(const std::vector<analysis::VerdictRow>& rows);
/// Writes acceptance_csv(rows) to `path` (a temporary file renamed into place: never half written).
void write_acceptance_csv(const std::string& path, const std::vector<analysis::VerdictRow>& rows);
/// "PASS", "FAIL" or "not assessed".
const char* status_text(const analysis::CriterionResult& r);

}  // namespace inerta::io
