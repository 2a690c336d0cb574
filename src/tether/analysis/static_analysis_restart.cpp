#include "tether/analysis/static_analysis.hpp"

// The restart side of StaticAnalysis: continuing from a saved state
// (resume) and the state a restart point saves (restart_state).

#include <cmath>
#include <cstdint>
#include <functional>

#include "tether/analysis/increment_controller.hpp"
#include "tether/analysis/procedure.hpp"
#include "tether/analysis/restart.hpp"
#include "tether/core/error.hpp"

namespace tether {

namespace {

using Refusal = std::function<void(const std::string&)>;  ///< throws InputError with the reason

/// The file must have one record for each contribution of `order` that has a
/// history in this model, and none for others.
void check_contribution_records(const std::vector<Contribution*>& order, const RestartState& state,
                                const Refusal& refuse) {
  std::vector<Contribution*> expected;
  std::vector<double> probe;
  for (Contribution* c : order) {
    probe.clear();
    c->save_state(probe);
    expected.push_back(probe.empty() ? nullptr : c);
  }
  std::size_t next = 0;
  for (const ContributionState& record : state.contributions) {
    if (record.index < 0 || record.index >= static_cast<std::int64_t>(order.size()))
      refuse("a contribution state refers to #" + std::to_string(record.index));
    const auto k = static_cast<std::size_t>(record.index);
    if (k < next) refuse("contribution states out of order");
    for (; next < k; ++next)
      if (expected[next]) refuse("no saved state for " + expected[next]->describe());
    if (!expected[k]) refuse("a saved state for " + order[k]->describe() + ", which has none in this deck");
    next = k + 1;
  }
  for (; next < order.size(); ++next)
    if (expected[next]) refuse("no saved state for " + expected[next]->describe());
}

/// Loads the checked records; a contribution may still refuse its record,
/// and the ones loaded before it then get their previous state back.
void load_contribution_states(const std::vector<Contribution*>& order, const RestartState& state,
                              const Refusal& refuse) {
  std::vector<std::vector<double>> previous;
  for (const ContributionState& record : state.contributions) {
    Contribution* c = order[static_cast<std::size_t>(record.index)];
    previous.emplace_back();
    c->save_state(previous.back());
    std::span<const double> in(record.values);
    std::string error;
    try {
      c->load_state(in);
      if (!in.empty()) error = std::to_string(in.size()) + " values too many in its saved state";
    } catch (const std::exception& e) {
      error = e.what();
    }
    if (!error.empty()) {
      for (std::size_t k = 0; k < previous.size(); ++k) {
        std::span<const double> back(previous[k]);
        order[static_cast<std::size_t>(state.contributions[k].index)]->load_state(back);
      }
      refuse(c->describe() + ": " + error);
    }
  }
}

}  // namespace

std::vector<Contribution*> StaticAnalysis::stateful_order() const {
  const Discretization& disc = *discretization_;
  std::vector<Contribution*> out;
  for (const auto& e : disc.elements()) out.push_back(e.get());
  for (const auto& c : disc.constraints()) out.push_back(c.get());
  for (const auto& c : disc.user_constraints()) out.push_back(c.get());
  for (const auto& pair : disc.contact_pairs()) out.push_back(pair.get());
  for (const auto& pair : disc.mortar_pairs()) out.push_back(pair.get());
  return out;
}

void StaticAnalysis::resume(const RestartState& state, const std::string& file) {
  const SourceLocation where{file, 0};
  const auto refuse = [&](const std::string& why) {
    throw InputError(where, "cannot continue this deck from the restart file: " + why);
  };
  const int n_steps = static_cast<int>(model_.steps.size());
  if (state.step < 1 || state.increment < 0) refuse("bad step " + std::to_string(state.step));
  const std::vector<Contribution*> order = stateful_order();
  const RestartFingerprint deck =
      restart_fingerprint(model_, *discretization_, static_cast<int>(order.size()), state.step);
  if (const std::string diff = fingerprint_differences(deck, state.fingerprint); !diff.empty())
    refuse("it was written for another model (" + (state.deck.empty() ? std::string("?") : state.deck) + "): " + diff);
  if (state.step > n_steps || state.fingerprint.history_steps != state.step)
    refuse("inconsistent step " + std::to_string(state.step) + " (the deck has " + std::to_string(n_steps) + ")");
  if (model_.restart_read && model_.restart_read->step > 0) {
    const RestartRead& want = *model_.restart_read;
    if (want.step != state.step || (want.increment > 0 && want.increment != state.increment))
      throw InputError(want.where,
                       "*RESTART, READ asks for step " + std::to_string(want.step) +
                           (want.increment > 0 ? " increment " + std::to_string(want.increment) : std::string()) +
                           ", but " + file + " holds step " + std::to_string(state.step) + " increment " +
                           std::to_string(state.increment) +
                           " (only the last state written is kept: OVERLAY); restart from that one or rerun");
  }
  const auto n = static_cast<std::size_t>(discretization_->dofs().n_dofs());
  if (state.u.size() != n)
    refuse("it holds " + std::to_string(state.u.size()) + " unknowns, the model has " + std::to_string(n));
  if (!state.step_completed) {
    const Step& step = model_.steps[static_cast<std::size_t>(state.step - 1)];
    if (state.u_step_start.size() != n) refuse("the unknowns at the start of the step are missing");
    if (!(state.dt > 0) || !std::isfinite(state.dt) || !(state.step_time >= 0) || state.step_time > step.period ||
        state.n_averaged < 0 || state.easy_in_row < 0)
      refuse("bad time-stepping state (step time " + format_time(state.step_time) + ", increment " +
             format_time(state.dt) + ")");
  }
  for (const auto* loads : {&state.cload_end, &state.pressure_end})
    for (const CarriedLoad& l : *loads)
      if (l.first < 0 || l.first > INT32_MAX || l.second < 0 || l.second > INT32_MAX) refuse("bad carried load");

  MotionState motion;
  if (!motion.load(state.motion, static_cast<Eigen::Index>(n))) refuse("bad dynamic state (velocities, accelerations)");
  check_contribution_records(order, state, refuse);
  load_contribution_states(order, state, refuse);
  u_ = Eigen::Map<const Eigen::VectorXd>(state.u.data(), static_cast<Eigen::Index>(n));
  total_time_ = state.total_time;
  cload_end_.clear();
  for (const CarriedLoad& l : state.cload_end)
    cload_end_[{static_cast<int>(l.first), static_cast<int>(l.second)}] = l.value;
  pressure_end_.clear();
  for (const CarriedLoad& l : state.pressure_end)
    pressure_end_[{static_cast<int>(l.first), static_cast<int>(l.second)}] = l.value;
  motion_ = std::move(motion);
  resume_ = std::make_unique<RestartState>(state);
  resume_->u.clear();
  resume_file_ = file;
}

RestartState StaticAnalysis::restart_state(int index, bool completed, const AnalysisSummary& summary,
                                           const IncrementController& clock, const Procedure& procedure,
                                           const Eigen::VectorXd& u_step_start) const {
  RestartState r;
  r.written_by = std::string("tether ") + TETHER_VERSION;
  r.deck = model_.deck_path;
  const std::vector<Contribution*> order = stateful_order();
  r.fingerprint = restart_fingerprint(model_, *discretization_, static_cast<int>(order.size()), index + 1);
  r.step = index + 1;
  clock.save(r);
  r.step_completed = completed;
  r.total_time = total_time_;
  procedure.save(r);
  r.steps_completed = summary.steps + (completed ? 1 : 0);
  r.increments = summary.increments;
  r.iterations = summary.iterations;
  r.cutbacks = summary.cutbacks;
  r.u.assign(u_.data(), u_.data() + u_.size());
  if (!completed) r.u_step_start.assign(u_step_start.data(), u_step_start.data() + u_step_start.size());
  motion_.save(r.motion);
  for (const auto& [key, value] : cload_end_) r.cload_end.push_back({key.first, key.second, value});
  for (const auto& [key, value] : pressure_end_) r.pressure_end.push_back({key.first, key.second, value});
  for (std::size_t k = 0; k < order.size(); ++k) {
    ContributionState c;
    c.index = static_cast<std::int64_t>(k);
    order[k]->save_state(c.values);
    if (!c.values.empty()) r.contributions.push_back(std::move(c));
  }
  return r;
}

}  // namespace tether
