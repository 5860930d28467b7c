// A DCB test record read from CSV: load, load-point opening and crack length per row, from a test
// machine's export or from a simulated DCB's history.csv, and the choice of the rows that are
// propagation points. The first non-empty line not starting with '#' is the header of column
// names; the separator is ',' (';' or a tab when the header has no comma). Every problem throws
// InputError naming the file, and the line for a bad row.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fracture/dcb_reduction.hpp"

namespace plyimpact::fracture {

/// Names of the three columns used; the defaults match a simulated DCB's history.
struct DcbColumns {
  std::string load = "load";            // P
  std::string opening = "opening";      // delta, load-point opening (both arms)
  std::string crack = "crack_length";   // a, measured from the load line
};

/// SI value of one unit of the file's numbers: metres per length unit, newtons per force unit.
struct DcbUnits {
  double length = 1, force = 1;
};

struct DcbRow {
  DcbPoint point;  // SI
  int line = 0;    // 1-based line in the file
};

struct DcbRecord {
  std::string file;
  std::vector<DcbRow> rows;
};

/// Which rows are propagation points.
///   crack_growth: a row whose crack length is larger than the previous row's (the load and
///                 opening at the moment the front reached a new length); the first row, and rows
///                 while the crack stands still (loading up to initiation), are not.
///   all_rows:     every row (a sheet listing only the propagation marks); a must then strictly
///                 increase from row to row.
enum class PropagationRule { crack_growth, all_rows };

/// @throws InputError (missing column, bad number, short row, unreadable file)
DcbRecord parse_dcb_record(std::string_view text, const std::string& file_label, const DcbColumns& columns,
                           const DcbUnits& units);
DcbRecord read_dcb_record(const std::string& path, const DcbColumns& columns, const DcbUnits& units);

/// The record with load and opening replaced by their centred moving average over 2 half_width + 1
/// rows (fewer at the ends); crack lengths unchanged. A simulated record carries the arms' vibration
/// row to row (about +-10 % of the load at 5 us rows on the shipped DCB), and a propagation point is
/// the one row where the front passed a pair, so which phase of the vibration it samples is chance; a
/// test machine's load cell and filter average it out. half_width 0 returns the record unchanged.
DcbRecord smoothed_record(const DcbRecord& record, int half_width);

/// The propagation points of `record` by `rule`, in order, with their lines.
/// @throws InputError when the crack length decreases anywhere (file:line), when a propagation point
/// has a non-positive load or opening (file:line), or when fewer than 3 points remain
std::vector<DcbRow> propagation_points(const DcbRecord& record, PropagationRule rule);

}  // namespace plyimpact::fracture
