// `trakbox elements FILE... [--to FORMAT] [--no-checksum] [--time ISO8601]`: what element files
// hold (name, catalog number, epoch, age, format, orbit type), or the same sets converted to a TLE or
// an OMM encoding; and the reading of element files that every orbit command shares (--no-checksum,
// problems reported on stderr).
#pragma once
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "cli/options.h"
#include "orbit/elements.h"

namespace tb::app {

int run_elements(std::vector<std::string> args);

// --no-checksum, as every orbit command describes it.
OptionSpec no_checksum_option();
orbit::ParseOptions checked_options(bool verify_checksums);
// Each problem as one line on `to`: "trakbox: error: FILE:LINE:COL: ..." or "trakbox: warning: ...".
void report_problems(const std::vector<orbit::ParseProblem>& problems, std::FILE* to);
// With --no-checksum: a warning for each set accepted despite a wrong checksum.
void report_accepted_checksums(std::string_view text, const std::string& file, std::FILE* to);

}  // namespace tb::app
