#include "tether/output/status_writer.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "tether/output/fortran_format.hpp"

#ifndef TETHER_VERSION
#define TETHER_VERSION "unknown"
#endif

namespace tether {

namespace {

/// Fortran E13.6: " 0.100000E+01".
std::string e13(double v) { return fmt::format("{:>13}", fortran_e(v, 6)); }

}  // namespace

StatusWriter::StatusWriter(std::filesystem::path file, const std::string& job, std::string_view dialect)
    : file_(std::move(file)), out_(file_, std::ios::binary | std::ios::trunc) {
  if (!out_) throw std::runtime_error("cannot create '" + file_.string() + "'");
  out_ << fmt::format(" tether {}  job {}{}\n SUMMARY OF JOB INFORMATION:\n", TETHER_VERSION, job,
                      dialect.empty() ? std::string() : fmt::format("  dialect {}", dialect))
       << "  STEP   INC  ATT  ITRS  TOTITRS      TOT TIME     STEP TIME      INC TIME      RESIDUAL\n";
  out_.flush();
}

void StatusWriter::write(const IncrementStatus& s) {
  out_ << fmt::format("{:6d}{:6d}{:5d}{:1}{:5d}{:9d} {} {} {} {}\n", s.step, s.increment, s.attempt,
                      s.converged ? ' ' : 'U', s.iterations, s.total_iterations, e13(s.total_time),
                      e13(s.step_time), e13(s.increment_size), e13(s.residual_norm));
  out_.flush();
}

void StatusWriter::finish(bool completed, const std::string& message) {
  if (finished_) return;
  finished_ = true;
  if (completed)
    out_ << " THE ANALYSIS HAS COMPLETED SUCCESSFULLY" << (message.empty() ? "" : ": " + message) << '\n';
  else
    out_ << " THE ANALYSIS HAS NOT BEEN COMPLETED: " << (message.empty() ? "reason unknown" : message) << '\n';
  out_.flush();
}

}  // namespace tether
