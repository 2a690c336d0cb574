#include "tether/output/output_schedule.hpp"

namespace tether {

bool is_due(const OutputRequest& request, int increment, bool last_in_step) {
  if (request.frequency <= 0) return false;
  return last_in_step || increment % request.frequency == 0;
}

}  // namespace tether
