#include <spar/study/run_limits.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace spar::study {

namespace {

/// The memory figures of a message: "1.3 GB" (6 significant digits are noise here: 3).
std::string gigabytes(double bytes) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g GB", bytes / 1e9);
  return buffer;
}

}  // namespace

std::string Range::text() const {
  return std::string(low_open ? "(" : "[") + significant(low) + ", " + significant(high) + (high_open ? ")" : "]");
}

long time_steps(double h, double t_end, const std::string& h_name, const std::string& t_end_name) {
  const std::string where = "options " + h_name + ", " + t_end_name;
  if (!(std::isfinite(h) && h > 0.0 && std::isfinite(t_end) && t_end > 0.0))
    throw Error(h_name + " = " + significant(h) + " and " + t_end_name + " = " + significant(t_end) +
                    " must be positive finite times", where, "give e.g. " + h_name + " 1e-3 " + t_end_name + " 1");
  if (h > t_end * (1 + 1e-12))
    throw Error("the step " + h_name + " = " + significant(h) + " s is longer than the span " + t_end_name +
                    " = " + significant(t_end) + " s: no step would be taken",
                where, "give a step no longer than the end time");
  const double steps = std::ceil(t_end / h - 1e-9);
  if (steps > max_time_steps)
    throw Error(t_end_name + " / " + h_name + " = " + significant(steps) + " steps, more than the " +
                    significant(max_time_steps) + " a run may take",
                where, "raise " + h_name + " or lower " + t_end_name);
  return static_cast<long>(steps);
}

void require_within_run(double time, const std::string& name, const std::string& what, double t_end,
                        const std::string& t_end_name) {
  if (time <= t_end * (1 + 1e-12)) return;
  throw Error(name + " = " + significant(time) + " s is later than the end of the run, " + t_end_name + " = " +
                  significant(t_end) + " s: " + what,
              "options " + name + ", " + t_end_name,
              "give " + name + " at most " + t_end_name + " (" + significant(t_end) + " s), or raise " + t_end_name);
}

void require_slender_beam(double length, const std::string& length_name, double thin, const std::string& thin_name,
                          double thick, const std::string& thick_name, double most) {
  const std::string where = "options " + length_name + ", " + thin_name + (thick_name == thin_name ? "" : ", " + thick_name);
  if (length < min_slenderness * thick)
    throw Error("a beam of " + length_name + " = " + significant(length) + " m and a section side " + thick_name +
                    " = " + significant(thick) + " m has a slenderness of " + significant(length / thick) +
                    ": a member shorter than " + significant(min_slenderness) +
                    " times its section's depth is a deep beam, not a beam (EN 1992-1-1 5.3.1)",
                where, "give " + length_name + " at least " + significant(min_slenderness * thick) + " m or a thinner section");
  if (length > most * thin)
    throw Error("a beam of " + length_name + " = " + significant(length) + " m and a section side " + thin_name +
                    " = " + significant(thin) + " m has a slenderness of " + significant(length / thin) +
                    ", more than " + significant(most) +
                    ": its axial stiffness swamps its bending stiffness in double precision (the digits lost grow "
                    "as the slenderness squared)",
                where, "give " + length_name + " at most " + significant(most * thin) + " m or a thicker section");
}

double physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page_size > 0 ? static_cast<double>(pages) * static_cast<double>(page_size) : 4e9;
}

double memory_budget() { return 0.5 * physical_memory(); }

int element_limit(const MemoryUse& memory) {
  const double a = memory.per_element_squared, b = memory.per_element, c = memory_budget();
  const double limit = a > 0.0 ? 2 * c / (b + std::sqrt(b * b + 4 * a * c)) : c / b;  // the root of a n² + b n = c
  return static_cast<int>(std::min(std::floor(limit), static_cast<double>(std::numeric_limits<int>::max())));
}

void require_memory(double elements, const MemoryUse& memory, const std::string& names, const std::string& given) {
  if (memory.bytes(elements) <= memory_budget()) return;
  char per_element[48];
  std::snprintf(per_element, sizeof per_element, "%.3g kB per element", memory.per_element / 1e3);
  const std::string count = given.empty() ? significant(elements) : "'" + given + "'";
  throw Error(count + " elements would need about " + gigabytes(memory.bytes(elements)) + " of memory (" +
                  per_element + (memory.per_element_squared > 0.0 ? " and a dense matrix of the model's size" : "") +
                  ", measured), more than the " + gigabytes(memory_budget()) + " a run may use (half of this machine's " +
                  gigabytes(physical_memory()) + ")",
              names, "give at most " + std::to_string(element_limit(memory)) + " elements");
}

}  // namespace spar::study
