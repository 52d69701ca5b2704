#include "hdf5_lock.hpp"

namespace spar::core::detail {

std::mutex& hdf5_mutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace spar::core::detail
