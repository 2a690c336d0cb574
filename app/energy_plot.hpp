#pragma once
/// \file The energy history of a dynamic job as a PNG next to its CSV
/// (JOB_energy.csv -> JOB_energy.png), drawn by matplotlib (DESIGN.md: plots
/// by matplotlib or gnuplot) in a child `python3` process: the system's
/// /usr/bin/python3 when it exists (scripts/install-deps.sh gives it
/// python3-matplotlib), else the first python3 on PATH.

#include <filesystem>
#include <string>

namespace tether::app {

/// Draws the columns of `csv` (tether's energy CSV: step, increment, time,
/// ALLKE, ALLSE, ALLWK, ALLFD, ALLVD, ALLPD, NUMERICAL, ETOTAL) against time
/// into `png`, titled `title`; columns that are zero throughout are left out.
/// Returns "" on success, else why no plot was written (no python3, no
/// matplotlib, a failed write): the caller warns, the analysis stands.
[[nodiscard]] std::string plot_energy(const std::filesystem::path& csv, const std::filesystem::path& png,
                                      const std::string& title);

}  // namespace tether::app
