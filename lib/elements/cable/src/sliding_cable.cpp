#include <spar/elements/cable/sliding_cable.hpp>

#include <spar/elements/rigid_body/point_mass_element.hpp>
#include <spar/elements/cable/rancf_merging.hpp>
#include <spar/elements/cable/rancf_segmentation.hpp>
#include <spar/error.hpp>
#include <spar/iga/quadrature.hpp>
#include <spar/iga/rational_bezier.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>

namespace spar::core {

template <int Dim>
SlidingCable<Dim>::SlidingCable(Model& model, const SlidingCableParameters& parameters)
    : parameters_(parameters) {
  constexpr const char* where = "core::SlidingCable";
  const int N = parameters_.elements;
  const double L = parameters_.length, x_s = parameters_.slider_position;
  if (N < 3) throw Error(std::to_string(N) + " elements", where, "use at least 3 elements");
  if (parameters_.two_sided_slider && parameters_.detachable)
    throw Error("a two-sided sliding node that may leave the cable", where,
                "use two_sided_slider or detachable, not both (release() joins one node block to the end)");
  if (!(x_s > 0.0 && x_s < L))
    throw Error("slider position " + std::to_string(x_s) + " is not inside (0, L)", where,
                "start the sliding node strictly inside the cable");
  standard_length_ = L / N;
  // Leave out node k0 + 1 so that the elements next to the slider span [k0, k0 + 2] L_std.
  const int k0 = std::clamp(static_cast<int>(std::floor(x_s / standard_length_ - 0.5)), 0, N - 2);
  std::vector<double> xs;
  for (int k = 0; k <= N; ++k) {
    if (k == k0 + 1) {
      slider_ = static_cast<int>(xs.size());
      xs.push_back(x_s);
    } else {
      xs.push_back(k * standard_length_);
    }
  }
  weights_.assign(N, Eigen::Vector4d::Ones());
  if (parameters_.shape) {
    if constexpr (Dim == 3)
      throw Error("a curved shape for a spatial cable", where, "give shapes to planar cables (SlidingCable<2>)");
    reference_ = std::make_shared<const CableReference>(parameters_.shape(xs));
    if (reference_->breakpoints() != xs)
      throw Error("the shape has breakpoints other than the mesh's " + std::to_string(xs.size()), where,
                  "cut the shape at the breakpoints it is given");
    for (int k = 0; k < N; ++k) weights_[k] = reference_->weights(k);
  }
  for (std::size_t i = 0; i < xs.size(); ++i) {
    Eigen::VectorXd node = Eigen::VectorXd::Zero(2 * Dim);
    if (reference_) {
      node = reference_->node(static_cast<int>(i));
    } else {
      node(0) = xs[i];
      node(Dim) = 1.0;
    }
    chain_.push_back(model.add_vector(node));
    materials_.push_back(model.add_vector(Eigen::VectorXd::Constant(1, xs[i])));
  }
  fixed_lengths_.resize(N);
  if (parameters_.two_sided_slider) right_slider_node_ = model.add_vector(model.state().vector(chain_[slider_]));
  for (int k = 0; k < N; ++k) {
    fixed_lengths_[k] = xs[k + 1] - xs[k];
    element_index_.push_back(model.add_element(make_element(model.state(), k, k == slider_ - 1 || k == slider_)));
  }
  mass_element_ = model.add_element(std::make_unique<PointMassElement>(PointMassParameters{
      .block = chain_[slider_], .dimension = Dim, .mass = parameters_.slider_mass, .name = "sliding mass"}));
  if (parameters_.detachable) particle_ = model.add_vector(Eigen::VectorXd::Zero(Dim));
}

template <int Dim>
int SlidingCable<Dim>::node_block(int position, int k) const {
  return position == slider_ && k == slider_ && right_slider_node_ >= 0 ? right_slider_node_ : chain_[position];
}

template <int Dim>
std::unique_ptr<Element> SlidingCable<Dim>::make_element(const Configuration& q, int k, bool ale) const {
  RancfCableParameters p;
  p.reference = reference_;
  p.node_a = node_block(k, k);
  p.node_b = node_block(k + 1, k);
  p.section = parameters_.section;
  p.weights = weights_[k];
  p.quadrature_points = parameters_.quadrature_points;
  p.name = (ale ? "ALE cable element " : "cable element ") + std::to_string(k);
  if (ale) {
    p.material_a = materials_[k];
    p.material_b = materials_[k + 1];
    return std::make_unique<AleRancfCableElement<Dim>>(p);
  }
  p.length = fixed_lengths_[k];
  p.material_start = q.vector(materials_[k])(0);
  return std::make_unique<RancfCableElement<Dim>>(p);
}

template <int Dim>
double SlidingCable<Dim>::element_length(const Configuration& q, int k) const {
  return q.vector(materials_[k + 1])(0) - q.vector(materials_[k])(0);
}

template <int Dim>
Eigen::MatrixXd SlidingCable<Dim>::sample_centerline(const Configuration& q, int per_element) const {
  const int N = static_cast<int>(weights_.size());
  Eigen::MatrixXd points = Eigen::MatrixXd::Zero(N * per_element + 1, 3);
  for (int k = 0; k < N; ++k)
    for (int j = 0; j <= per_element; ++j) {
      if (j == per_element && k + 1 < N) continue;
      const Eigen::Vector4d s = iga::rancf_shape_functions(static_cast<double>(j) / per_element, weights_[k],
                                                           element_length(q, k));
      const auto a = q.vector(node_block(k, k)), b = q.vector(node_block(k + 1, k));
      points.row(k * per_element + j).head<Dim>() =
          (s(0) * a.head(Dim) + s(1) * a.tail(Dim) + s(2) * b.head(Dim) + s(3) * b.tail(Dim)).transpose();
    }
  return points;
}

template <int Dim>
Eigen::MatrixXd SlidingCable<Dim>::sample_centerline(const Configuration& q, int per_element, Eigen::Index rows) const {
  Eigen::MatrixXd points = sample_centerline(q, per_element);
  const Eigen::Index sampled = points.rows();
  if (rows < sampled)
    throw Error(std::to_string(rows) + " rows for a centerline of " + std::to_string(sampled) + " points",
                "core::SlidingCable::sample_centerline", "give at least elements · per_element + 1 rows");
  points.conservativeResize(rows, 3);
  for (Eigen::Index i = sampled; i < rows; ++i) points.row(i) = points.row(sampled - 1);
  return points;
}

template <int Dim>
Eigen::Matrix<double, Dim, 1> SlidingCable<Dim>::mass_position(const Configuration& q) const {
  if (released_) return q.vector(particle_);
  return q.vector(chain_[slider_]).head(Dim);
}

template <int Dim>
double SlidingCable<Dim>::slider_coordinate(const Configuration& q) const {
  return released_ ? std::nan("") : q.vector(materials_[slider_])(0);
}

template <int Dim>
double SlidingCable<Dim>::deformed_length(const Configuration& q) const {
  const iga::GaussRule rule = iga::gauss_legendre(8);
  double total = 0.0;
  for (int k = 0; k < static_cast<int>(weights_.size()); ++k) {
    const double l = element_length(q, k);
    const auto a = q.vector(node_block(k, k)), b = q.vector(node_block(k + 1, k));
    for (std::size_t g = 0; g < rule.points.size(); ++g) {
      const Eigen::Matrix4d sh = iga::rancf_shape_function_derivatives(0.5 * (rule.points[g] + 1.0), weights_[k]);
      const Eigen::Matrix<double, Dim, 1> r_u =
          sh(0, 1) * a.head(Dim) + l * sh(1, 1) * a.tail(Dim) + sh(2, 1) * b.head(Dim) + l * sh(3, 1) * b.tail(Dim);
      total += 0.5 * rule.weights[g] * r_u.norm();  // ∫ |r_x| dx = ∫₀¹ |r_u| du
    }
  }
  return total;
}

template <int Dim>
std::pair<double, double> SlidingCable<Dim>::controlled_length_ratios(const Configuration& q) const {
  const int s = slider_, last = static_cast<int>(chain_.size()) - 1;
  double shortest = std::numeric_limits<double>::infinity(), longest = 0.0;
  for (int k = 0; k < last; ++k) {
    if ((k == s - 1 || k == s) && (s - 1 == 0 || s + 1 == last)) continue;
    const double ratio = element_length(q, k) / standard_length_;
    shortest = std::min(shortest, ratio);
    longest = std::max(longest, ratio);
  }
  return {shortest, longest};
}

template <int Dim>
std::vector<int> SlidingCable<Dim>::fixed_dofs(const Configuration& q) const {
  std::vector<int> dofs;
  for (std::size_t i = 0; i < materials_.size(); ++i)
    if (released_ || static_cast<int>(i) != slider_) dofs.push_back(q.blocks[materials_[i]].offset);
  if (particle_ >= 0 && !released_)
    for (int i = 0; i < Dim; ++i) dofs.push_back(q.blocks[particle_].offset + i);
  if (released_) {
    for (int i = 0; i < 2 * Dim; ++i) dofs.push_back(q.blocks[dead_node_].offset + i);
    dofs.push_back(q.blocks[dead_material_].offset);
  }
  std::sort(dofs.begin(), dofs.end());
  return dofs;
}

template <int Dim>
void SlidingCable<Dim>::fix_supports(Model& model, const CableSupports& supports) const {
  std::vector<int> fixed = fixed_dofs(model.state());
  for (const auto& [end, count] : {std::pair{chain_.front(), supports.left}, {chain_.back(), supports.right}}) {
    if (count < 0 || count > 2 * Dim)
      throw Error("a support fixing " + std::to_string(count) + " coordinates of an end node [r, r_x]",
                  "core::SlidingCable::fix_supports",
                  "fix 0 to " + std::to_string(2 * Dim) + " coordinates (" + std::to_string(Dim) +
                      " pins the position, " + std::to_string(2 * Dim) + " clamps the slope too)");
    for (int i = 0; i < count; ++i) fixed.push_back(model.state().blocks[end].offset + i);
  }
  std::sort(fixed.begin(), fixed.end());
  model.set_fixed_dofs(fixed);
}

template <int Dim>
double SlidingCable<Dim>::release_length(double time_step, double material_rate) const {
  return std::max(0.1 * standard_length_, 4 * time_step * std::fabs(material_rate));
}

template <int Dim>
bool SlidingCable<Dim>::near_end(const Configuration& q, int end, double min_length) const {
  const int last = static_cast<int>(chain_.size()) - 1;
  if (released_) return false;
  if (end == last && slider_ + 1 == last) return element_length(q, slider_) < min_length;
  if (end == 0 && slider_ - 1 == 0) return element_length(q, 0) < min_length;
  return false;
}

template <int Dim>
void SlidingCable<Dim>::release(Model& model, Eigen::MatrixXd& P) {
  constexpr const char* where = "core::SlidingCable::release";
  const int s = slider_, last = static_cast<int>(chain_.size()) - 1;
  if (particle_ < 0 || released_)
    throw Error(particle_ < 0 ? "no particle block reserved" : "the mass has already left", where,
                "build the cable with detachable = true and release once");
  if (s + 1 != last && s - 1 != 0)
    throw Error("the sliding node is not next to an end element", where, "release at a free end");
  Configuration& q = model.state();
  // The sliding node S becomes the cable's end: the short end element (S to the old end node E)
  // is removed with its material, E's blocks are fixed from then on, and the inner element keeps
  // its weights and its current length (fixed). S is held at its material point: its rates are
  // the material velocity and slope rate there (eq. R30 at the inner element's end, ẋ_g = ẋ_S).
  // The mass becomes a particle at r_S with velocity ṙ_S.
  const bool right = s + 1 == last;
  const int k_inner = right ? s - 1 : s, k_end = right ? s : s - 1, end = right ? last : 0;
  const double u_node = right ? 1.0 : 0.0, l = element_length(q, k_inner);
  const auto a = q.vector(chain_[k_inner]), b = q.vector(chain_[k_inner + 1]);
  const Eigen::Matrix4d sh = iga::rancf_shape_function_derivatives(u_node, weights_[k_inner]);
  const Eigen::Matrix<double, Dim, 1> r_uu =
      sh(0, 2) * a.head(Dim) + l * sh(1, 2) * a.tail(Dim) + sh(2, 2) * b.head(Dim) + l * sh(3, 2) * b.tail(Dim);
  const Eigen::Matrix<double, Dim, 1> r_x = q.vector(chain_[s]).template tail<Dim>();
  const int n = q.dof_count();
  const int node = q.blocks[chain_[s]].offset, x = q.blocks[materials_[s]].offset, p = q.blocks[particle_].offset;
  const int dead = q.blocks[chain_[end]].offset, dead_x = q.blocks[materials_[end]].offset;
  P = Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i < Dim; ++i) {
    P.row(p + i).setZero();
    P(p + i, node + i) = 1.0;
    P(node + i, x) = -r_x(i);
    P(node + Dim + i, x) = -r_uu(i) / (l * l);
  }
  P.row(x).setZero();
  for (int i = 0; i < 2 * Dim; ++i) P.row(dead + i).setZero();
  P.row(dead_x).setZero();
  q.vector(particle_) = q.vector(chain_[s]).template head<Dim>();
  model.replace_element(mass_element_, std::make_unique<PointMassElement>(PointMassParameters{
                                           .block = particle_, .dimension = Dim,
                                           .mass = parameters_.slider_mass, .name = "released mass"}));
  const int removed = element_index_[k_end];
  model.remove_element(removed);
  for (int& index : element_index_)
    if (index > removed) --index;
  if (mass_element_ > removed) --mass_element_;
  dead_node_ = chain_[end];
  dead_material_ = materials_[end];
  chain_.erase(chain_.begin() + end);
  materials_.erase(materials_.begin() + end);
  element_index_.erase(element_index_.begin() + k_end);
  weights_.erase(weights_.begin() + k_end);
  fixed_lengths_.erase(fixed_lengths_.begin() + k_end);
  const int k_kept = right ? k_inner : k_inner - 1;
  fixed_lengths_[k_kept] = l;
  released_ = true;
  slider_ = -1;
  model.replace_element(element_index_[k_kept], make_element(q, k_kept, false));
}

template <int Dim>
std::optional<LengthControlEvent> SlidingCable<Dim>::control_length(Model& model, double time,
                                                                     Eigen::MatrixXd& P) {
  if (released_) return std::nullopt;
  Configuration& q = model.state();
  const int s = slider_, last = static_cast<int>(chain_.size()) - 1;
  const double limit = 1.5 * standard_length_;
  // d = +1: the element on the left grows (slider moving right); −1: the right one.
  int d = 0;
  if (element_length(q, s - 1) > limit && s + 2 <= last) d = 1;
  else if (element_length(q, s) > limit && s - 2 >= 0) d = -1;
  if (d == 0) return std::nullopt;

  // The growing element (far node F, slider S), the node D to delete and the node beyond it.
  const int far = s - d, deleted = s + d, beyond = s + 2 * d;
  const int k_grow = d == 1 ? s - 1 : s;  // element index of the growing element
  // Old growing element in its own order [A, B] (A left).
  const int a = d == 1 ? far : s, b = d == 1 ? s : far;
  Eigen::Matrix<double, 4 * Dim, 1> e;
  e << q.vector(node_block(a, k_grow)), q.vector(node_block(b, k_grow));
  const double x_a = q.vector(materials_[a])(0), x_b = q.vector(materials_[b])(0), l = x_b - x_a;
  const double u_h = d == 1 ? standard_length_ / l : 1.0 - standard_length_ / l;
  const RancfSplit<Dim> split = split_rancf_element<Dim>(
      e, x_a, x_b, weights_[k_grow], u_h, Eigen::Matrix<double, 4 * Dim + 2, 1>::Zero());

  // Merge the elements on both sides of D into one from S to `beyond` (000 §4.2).
  const int m_a = d == 1 ? s : beyond, m_b = d == 1 ? beyond : s;
  Eigen::Matrix<double, 4 * Dim, 1> e_merged;
  e_merged << q.vector(node_block(m_a, m_a)), q.vector(node_block(m_b, m_a));
  const Eigen::Matrix<double, Dim, 1> r_d = q.vector(chain_[deleted]).template head<Dim>();
  LengthControlEvent event;
  event.time = time;
  event.grown_element = k_grow;
  event.grown_weights = weights_[k_grow];
  event.merged_near_weights = weights_[d == 1 ? s : s - 1];
  event.merged_far_weights = weights_[d == 1 ? s + 1 : s - 2];
  if (parameters_.rational) {
    const RancfMergeWeights merged = merge_rancf_weights<Dim>(
        e_merged, r_d, q.vector(materials_[m_a])(0), q.vector(materials_[deleted])(0),
        q.vector(materials_[m_b])(0), parameters_.max_merge_weight);
    event.merged_weights = merged.weights;
    event.merge_fallback = merged.fallback;
    event.merge_bounded = merged.bounded;
    event.merge_miss = merged.miss;
  } else {
    event.merged_weights = Eigen::Vector4d::Ones();
    const Eigen::Vector4d sh = iga::rancf_shape_functions(
        (q.vector(materials_[deleted])(0) - q.vector(materials_[m_a])(0)) /
            (q.vector(materials_[m_b])(0) - q.vector(materials_[m_a])(0)),
        Eigen::Vector4d::Ones(), q.vector(materials_[m_b])(0) - q.vector(materials_[m_a])(0));
    Eigen::Matrix<double, Dim, 1> r = Eigen::Matrix<double, Dim, 1>::Zero();
    for (int k = 0; k < 4; ++k) r += sh(k) * e_merged.template segment<Dim>(k * Dim);
    event.merge_miss = (r - r_d).norm();
  }
  const Eigen::Vector4d left = split.left_weights / split.left_weights(3);
  const Eigen::Vector4d right = split.right_weights / split.right_weights(3);
  event.split_weights_far = d == 1 ? left : right;
  event.split_weights_near = d == 1 ? right : left;

  // P: identity but for D's blocks, which now hold H, held at its material point x_H (a fixed
  // coordinate from now on): the material rates at x_H (eq. R30) over the growing element's dofs.
  const int n = q.dof_count();
  P = Eigen::MatrixXd::Identity(n, n);
  std::vector<int> columns;
  for (int block : {node_block(a, k_grow), node_block(b, k_grow), materials_[a], materials_[b]})
    for (int i = 0; i < q.blocks[block].size; ++i) columns.push_back(q.blocks[block].offset + i);
  const int node_offset = q.blocks[chain_[deleted]].offset, x_offset = q.blocks[materials_[deleted]].offset;
  for (int r = 0; r <= 2 * Dim; ++r) {
    const int row = r < 2 * Dim ? node_offset + r : x_offset;
    P.row(row).setZero();
    for (std::size_t c = 0; c < columns.size(); ++c) P(row, columns[c]) = split.material_jacobian(r, static_cast<int>(c));
  }
  q.vector(chain_[deleted]) = split.node.template head<2 * Dim>();
  q.vector(materials_[deleted])(0) = split.node(2 * Dim);

  // Relabel: H (D's blocks) goes between F and S; S moves one place towards `beyond`.
  std::swap(chain_[s], chain_[deleted]);
  std::swap(materials_[s], materials_[deleted]);
  slider_ = s + d;
  // Elements (chain positions k to k + 1) after the relabelling.
  const int far_element = d == 1 ? s - 1 : s;   // F–H, fixed length L_std
  const int k_near = d == 1 ? s : s - 1;        // H–S, ALE
  const int k_merged = d == 1 ? s + 1 : s - 2;  // S–beyond, ALE
  weights_[far_element] = event.split_weights_far;
  weights_[k_near] = event.split_weights_near;
  weights_[k_merged] = event.merged_weights;
  fixed_lengths_[far_element] = standard_length_;
  model.replace_element(element_index_[far_element], make_element(q, far_element, false));
  model.replace_element(element_index_[k_near], make_element(q, k_near, true));
  model.replace_element(element_index_[k_merged], make_element(q, k_merged, true));
  event.description = std::string(d == 1 ? "slider moving +x" : "slider moving -x") +
                      ": split element " + std::to_string(k_grow) + " at u_H = " + std::to_string(u_h) +
                      ", merged across node block " + std::to_string(chain_[s]);
  return event;
}

template class SlidingCable<2>;
template class SlidingCable<3>;

}  // namespace spar::core
