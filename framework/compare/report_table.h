// The comparison as a table of text cells, one row per solver: the single source of the columns
// that the terminal, report.md and report.html show (report.json keeps the raw numbers).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "framework/compare/comparison.h"

namespace upf {

struct ReportTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

ReportTable make_report_table(const Comparison& c);

// Columns padded to a common width, for the terminal.
std::string format_text_table(const ReportTable& table);

// "completed", or "unstable at t = 0.1234 s".
std::string status_text(const CompareRow& row);

// `digits` significant digits; "n/a" for NaN or infinity, so a missing probe cannot break a report.
std::string format_number(double value, int digits = 4);

// What the report says about the comparison as a whole (scene, particles, threads, date ...).
std::vector<std::pair<std::string, std::string>> report_facts(const Comparison& c);

// One sentence per fixed column, printed under the table in the reports.
std::vector<std::pair<std::string, std::string>> column_notes();

}  // namespace upf
