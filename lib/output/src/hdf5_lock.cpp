#include "hdf5_lock.hpp"

namespace spar::output::detail {

std::mutex& hdf5_mutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace spar::output::detail
