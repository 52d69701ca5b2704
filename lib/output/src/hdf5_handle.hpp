#pragma once
/// \file
/// An HDF5 identifier closed at the end of its scope, and the link-creation properties with which
/// the results files make the groups in a dataset's name.

#include <hdf5.h>

namespace spar::output::detail {

/// Closes an HDF5 identifier when it goes out of scope (also on a throw).
class Hid {
public:
  Hid(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Hid() {
    if (id_ >= 0) close_(id_);
  }
  Hid(const Hid&) = delete;
  Hid& operator=(const Hid&) = delete;
  operator hid_t() const { return id_; }
  bool valid() const { return id_ >= 0; }

private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// A link-creation property list that creates missing intermediate groups; the caller closes it.
inline hid_t intermediate_groups() {
  const hid_t properties = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(properties, 1);
  return properties;
}

}  // namespace spar::output::detail
