#include <spar/elements/cable/rancf_cable_element.hpp>

#include <spar/core/dual.hpp>
#include <spar/error.hpp>

#include "rancf_kernel.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <type_traits>

namespace spar::core {

RancfSection RancfSection::circular(double radius, double young_modulus, double density) {
  const double area = std::numbers::pi * radius * radius, inertia = area * radius * radius / 4;
  return {.axial_stiffness = young_modulus * area, .bending_stiffness = young_modulus * inertia,
          .mass_per_length = density * area};
}

namespace {

template <class T, int Dim>
using LocalVector = Eigen::Matrix<T, 4 * Dim, 1>;

template <int Dim>
void check_parameters(const RancfCableParameters& p, bool ale, const char* where) {
  const auto positive = [](double x) { return x > 0.0 && std::isfinite(x); };
  if (p.node_a < 0 || p.node_b < 0)
    throw Error("node blocks " + std::to_string(p.node_a) + ", " + std::to_string(p.node_b) +
                    " are not set",
                where, "give the vector blocks [r, r_x] of both end nodes");
  if (ale && (p.material_a < 0 || p.material_b < 0))
    throw Error("the material-coordinate blocks are not set", where,
                "give the scalar vector blocks holding x_A and x_B");
  if (!ale && !positive(p.length))
    throw Error("reference length " + std::to_string(p.length) + " is not positive", where,
                "give l > 0");
  if (!positive(p.section.axial_stiffness) || !(p.section.bending_stiffness >= 0.0) ||
      !positive(p.section.mass_per_length) || !(p.section.damping_coefficient >= 0.0))
    throw Error("section EA = " + std::to_string(p.section.axial_stiffness) +
                    ", EI = " + std::to_string(p.section.bending_stiffness) +
                    ", rho A = " + std::to_string(p.section.mass_per_length) +
                    ", c = " + std::to_string(p.section.damping_coefficient) + " is not physical",
                where, "give EA > 0, EI ≥ 0, rho A > 0 and c ≥ 0");
  for (int i = 0; i < 4; ++i)
    if (!positive(p.weights(i)))
      throw Error("weight w" + std::to_string(i) + " = " + std::to_string(p.weights(i)) +
                      " is not a finite number > 0",
                  where, "give positive weights (000 eq. (9))");
  if (p.reference && Dim == 3)
    throw Error("a curved reference shape for a spatial cable", where,
                "give the reference to planar (2D) cables: a spatial curvature vector has no "
                "material frame to keep its reference direction in");
  if (p.reference && !std::isfinite(p.material_start))
    throw Error("material start " + std::to_string(p.material_start) + " is not finite", where,
                "give the material coordinate of node A");
  if (p.quadrature_points < 2 || p.quadrature_points > 16)
    throw Error(std::to_string(p.quadrature_points) + " Gauss points", where,
                "use 2 … 16 points (5 integrates the ANCF mass matrix and strain energy exactly)");
}

template <class T, int Dim, class Derived>
rancf::Nodal<T, Dim> nodal(const Eigen::MatrixBase<Derived>& local) {
  rancf::Nodal<T, Dim> e;
  for (int k = 0; k < 4; ++k) e[k] = local.template segment<Dim>(k * Dim);
  return e;
}

template <class T, int Dim>
rancf::Nodal<T, Dim> zero_nodal() {
  rancf::Nodal<T, Dim> e;
  for (auto& v : e) v.setConstant(T(0.0));
  return e;
}

void check_block_size(const Configuration& q, int block, int size, const char* what,
                      const std::string& name) {
  if (q.is_frame(block) || q.blocks[block].size != size)
    throw Error(std::string(what) + " block " + std::to_string(block) + " is not a vector block of " +
                    std::to_string(size) + " entries",
                name, "build the element on vector blocks [r, r_x] (2·Dim) and scalar x blocks");
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// What both elements share.

RancfCableBase::RancfCableBase(const RancfCableParameters& parameters, int dim, bool ale, const char* where)
    : parameters_(parameters), blocks_{parameters.node_a, parameters.node_b} {
  if (ale) blocks_.insert(blocks_.end(), {parameters.material_a, parameters.material_b});
  if (dim == 2)
    check_parameters<2>(parameters_, ale, where);
  else
    check_parameters<3>(parameters_, ale, where);
  table_ = rancf::quadrature_table(parameters_.weights, parameters_.quadrature_points);
}

// ---------------------------------------------------------------------------------------------
// Fixed-length RANCF element.

template <int Dim>
RancfCableElement<Dim>::RancfCableElement(const RancfCableParameters& parameters)
    : RancfCableBase(parameters, Dim, false, "core::RancfCableElement") {
  if (parameters_.reference)
    for (const rancf::QuadraturePoint& p : table_)
      reference_table_.push_back(
          parameters_.reference->at(parameters_.material_start + p.u * parameters_.length));
  // 000 eq. (19) with constant l: M = ρA l ∫₀¹ SᵀS du = m ⊗ I, m_ij = ρA l ∫ σ_i σ_j du (eq. R9).
  shape_mass_.setZero();
  for (const rancf::QuadraturePoint& p : table_) {
    Eigen::Vector4d sigma;
    for (int k = 0; k < 4; ++k) sigma(k) = rancf::sigma(p, k, 0, parameters_.length);
    shape_mass_ += (parameters_.section.mass_per_length * parameters_.length * p.weight) * sigma *
                   sigma.transpose();
  }
}

namespace {

/// The Kelvin–Voigt force alone (eq. R13) at nodal e, length l and rates, into `force` (4·Dim
/// entries, then ∂D/∂ẋ_A and ∂D/∂ẋ_B when it has 4·Dim + 2): the element's dissipative force,
/// whose work the energy balance books as physical dissipation (docs/dynamics.md D8).
template <int Dim>
void add_dissipative_force(const RancfCableParameters& parameters, const std::vector<rancf::QuadraturePoint>& table,
                           const rancf::Nodal<double, Dim>& e, double l, const rancf::Nodal<double, Dim>& e_dot,
                           double x_a_dot, double x_b_dot, Eigen::VectorXd& force) {
  rancf::Nodal<double, Dim> f_e = zero_nodal<double, Dim>();
  double f_a = 0.0, f_b = 0.0;
  rancf::viscous_force<double, Dim>(parameters.section, table, e, l, e_dot, x_a_dot, x_b_dot, f_e, f_a, f_b);
  for (int k = 0; k < 4; ++k) force.template segment<Dim>(k * Dim) += f_e[k];
  if (force.size() == 4 * Dim + 2) {
    force(4 * Dim) += f_a;
    force(4 * Dim + 1) += f_b;
  }
}

}  // namespace

template <int Dim>
void RancfCableElement<Dim>::compute(const ElementInput& in, const ElementRequest& request,
                                     ElementOutput& out) const {
  constexpr int n = 4 * Dim;
  const Configuration& q = *in.q;
  check_block_size(q, blocks_[0], 2 * Dim, "node", parameters_.name);
  check_block_size(q, blocks_[1], 2 * Dim, "node", parameters_.name);
  LocalVector<double, Dim> local;
  local << q.vector(blocks_[0]), q.vector(blocks_[1]);
  const double l = parameters_.length;

  // Strain energy U(e), f_int = ∂U/∂e (eq. R5) and the Kelvin–Voigt force (eq. R13, zero
  // material rates); K and C from one pass in duals seeded on e (and ė when damped).
  const bool viscous = in.dynamic() && parameters_.section.damping_coefficient > 0.0;
  LocalVector<double, Dim> rate = LocalVector<double, Dim>::Zero();
  if (viscous) gather(q, blocks_, *in.velocity, rate);
  const auto internal = [&]<class T>(const rancf::Nodal<T, Dim>& e, const rancf::Nodal<T, Dim>& e_dot,
                                     rancf::Nodal<T, Dim>& force) {
    T grad_l(0.0), f_a(0.0), f_b(0.0), grad_material[2] = {T(0.0), T(0.0)};
    std::array<ReferenceStrain<T>, 16> reference;
    for (std::size_t g = 0; g < reference_table_.size(); ++g) {
      const ReferenceStrain<double>& r = reference_table_[g];
      reference[g] = {T(r.axial), T(r.axial_slope), T(r.curvature), T(r.curvature_slope)};
    }
    const T energy = rancf::strain_energy<T, Dim>(parameters_.section, table_, e, T(l), force, grad_l,
                                                  reference_table_.empty() ? nullptr : reference.data(),
                                                  grad_material);
    if (viscous)
      rancf::viscous_force<T, Dim>(parameters_.section, table_, e, T(l), e_dot, T(0.0), T(0.0), force,
                                   f_a, f_b);
    out.energy.strain = value_of(energy);
  };
  const auto with_duals = [&]<int N>(std::integral_constant<int, N>) {
    using D = Dual<N>;
    rancf::Nodal<D, Dim> e, e_dot;
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < Dim; ++i) {
        e[k](i) = D::variable(local(k * Dim + i), k * Dim + i);
        e_dot[k](i) = N > n ? D::variable(rate(k * Dim + i), n + k * Dim + i) : D(rate(k * Dim + i));
      }
    rancf::Nodal<D, Dim> force = zero_nodal<D, Dim>();
    internal(e, e_dot, force);
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < Dim; ++i) {
        const D& f = force[k](i);
        if (request.residual) out.residual(k * Dim + i) += f.value;
        if (request.stiffness) out.stiffness.row(k * Dim + i) += f.grad.template head<n>().transpose();
        if constexpr (N > n)
          if (request.damping) out.damping.row(k * Dim + i) += f.grad.template tail<n>().transpose();
      }
  };
  if (viscous && request.damping)
    with_duals(std::integral_constant<int, 2 * n>{});
  else if (request.stiffness)
    with_duals(std::integral_constant<int, n>{});
  else {
    rancf::Nodal<double, Dim> force = zero_nodal<double, Dim>();
    internal(nodal<double, Dim>(local), nodal<double, Dim>(rate), force);
    if (request.residual)
      for (int k = 0; k < 4; ++k) out.residual.template segment<Dim>(k * Dim) += force[k];
  }

  // Gravity (eq. R6): linear in e at fixed l, no stiffness.
  const Eigen::Matrix<double, Dim, 1> g = in.load_factor * in.gravity.template head<Dim>();
  rancf::Nodal<double, Dim> grad_g = zero_nodal<double, Dim>();
  double grad_gl = 0.0;
  out.energy.gravity = rancf::gravity_potential<double, Dim>(
      parameters_.section.mass_per_length, table_, nodal<double, Dim>(local), l, g, grad_g, grad_gl);
  if (request.residual)
    for (int k = 0; k < 4; ++k) out.residual.template segment<Dim>(k * Dim) += grad_g[k];

  if (request.energy && viscous)
    add_dissipative_force<Dim>(parameters_, table_, nodal<double, Dim>(local), l, nodal<double, Dim>(rate), 0.0, 0.0,
                               out.dissipative_force);

  if (!in.dynamic()) return;
  // Inertia: M v̇ with the constant M = m ⊗ I (000 §2: no quadratic-velocity terms).
  LocalVector<double, Dim> v, a;
  gather(q, blocks_, *in.velocity, v);
  gather(q, blocks_, *in.acceleration, a);
  const auto as_matrix = [](const LocalVector<double, Dim>& x) {
    return Eigen::Map<const Eigen::Matrix<double, Dim, 4>>(x.data());
  };
  const Eigen::Matrix<double, Dim, 4> Ma = as_matrix(a) * shape_mass_;  // m symmetric
  if (request.residual)
    out.residual += Eigen::Map<const LocalVector<double, Dim>>(Ma.data());
  if (request.mass)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        out.mass.template block<Dim, Dim>(i * Dim, j * Dim).diagonal().setConstant(shape_mass_(i, j));
  out.energy.kinetic = 0.5 * (as_matrix(v) * shape_mass_).cwiseProduct(as_matrix(v)).sum();
}

// ---------------------------------------------------------------------------------------------
// ALE-RANCF element.

namespace {

/// The ALE-RANCF residual (docs/rancf.md eq. R12) at local q = [e, x_A, x_B], v, a:
/// ∂U/∂q + ∂V/∂q (+ the inertial force R11 when dynamic). Returns the energies in `energy`.
template <class T, int Dim>
void ale_residual(const RancfCableParameters& parameters,
                  const std::vector<rancf::QuadraturePoint>& table,
                  const Eigen::Matrix<T, 4 * Dim + 2, 1>& q, const Eigen::Matrix<T, 4 * Dim + 2, 1>& v,
                  const Eigen::Matrix<T, 4 * Dim + 2, 1>& a, bool dynamic,
                  const Eigen::Matrix<double, Dim, 1>& g, Eigen::Matrix<T, 4 * Dim + 2, 1>& r,
                  ElementEnergy& energy) {
  constexpr int n = 4 * Dim + 2;
  const auto e = nodal<T, Dim>(q.template head<4 * Dim>());
  const T& x_a = q(n - 2);
  const T& x_b = q(n - 1);
  const T l = x_b - x_a;
  rancf::Nodal<T, Dim> f_e = zero_nodal<T, Dim>();
  T f_l(0.0);
  // U and V depend on x_A, x_B through l (eqs. R5, R6): ∂/∂x_A = −∂/∂l, ∂/∂x_B = ∂/∂l; with a
  // reference shape U also depends on them through the Gauss points' material coordinates
  // x_g = x_A + u_g l (eq. R5a).
  std::array<ReferenceStrain<T>, 16> reference;
  if (parameters.reference)
    for (std::size_t k = 0; k < table.size(); ++k) reference[k] = parameters.reference->at(T(x_a + T(table[k].u) * l));
  T grad_material[2] = {T(0.0), T(0.0)};
  energy.strain = value_of(rancf::strain_energy<T, Dim>(parameters.section, table, e, l, f_e, f_l,
                                                        parameters.reference ? reference.data() : nullptr,
                                                        grad_material));
  energy.gravity = value_of(rancf::gravity_potential<T, Dim>(parameters.section.mass_per_length,
                                                             table, e, l, g, f_e, f_l));
  T f_a = grad_material[0] - f_l, f_b = grad_material[1] + f_l;
  if (dynamic) {
    const auto e_dot = nodal<T, Dim>(v.template head<4 * Dim>());
    const auto e_acc = nodal<T, Dim>(a.template head<4 * Dim>());
    energy.kinetic = value_of(rancf::ale_inertia<T, Dim>(
        parameters.section.mass_per_length, table, e, x_a, x_b, e_dot, v(n - 2), v(n - 1), e_acc,
        a(n - 2), a(n - 1), f_e, f_a, f_b));
    if (parameters.section.damping_coefficient > 0.0)
      rancf::viscous_force<T, Dim>(parameters.section, table, e, l, e_dot, v(n - 2), v(n - 1), f_e,
                                   f_a, f_b);
  }
  for (int k = 0; k < 4; ++k) r.template segment<Dim>(k * Dim) = f_e[k];
  r(n - 2) = f_a;
  r(n - 1) = f_b;
}

}  // namespace

template <int Dim>
AleRancfCableElement<Dim>::AleRancfCableElement(const RancfCableParameters& parameters)
    : RancfCableBase(parameters, Dim, true, "core::AleRancfCableElement") {}

template <int Dim>
void AleRancfCableElement<Dim>::compute(const ElementInput& in, const ElementRequest& request,
                                        ElementOutput& out) const {
  constexpr int n = 4 * Dim + 2;
  using Local = Eigen::Matrix<double, n, 1>;
  const Configuration& q = *in.q;
  check_block_size(q, blocks_[0], 2 * Dim, "node", parameters_.name);
  check_block_size(q, blocks_[1], 2 * Dim, "node", parameters_.name);
  check_block_size(q, blocks_[2], 1, "material-coordinate", parameters_.name);
  check_block_size(q, blocks_[3], 1, "material-coordinate", parameters_.name);
  Local local_q, local_v = Local::Zero(), local_a = Local::Zero();
  local_q << q.vector(blocks_[0]), q.vector(blocks_[1]), q.vector(blocks_[2]), q.vector(blocks_[3]);
  if (!(local_q(n - 1) - local_q(n - 2) > 0.0))
    throw Error("x_B − x_A = " + std::to_string(local_q(n - 1) - local_q(n - 2)) +
                    " ≤ 0: the element has no material left",
                parameters_.name, "control the element lengths (merge it) before it vanishes");
  const bool dynamic = in.dynamic();
  if (dynamic) {
    gather(q, blocks_, *in.velocity, local_v);
    gather(q, blocks_, *in.acceleration, local_a);
  }
  const Eigen::Matrix<double, Dim, 1> g = in.load_factor * in.gravity.template head<Dim>();

  if (request.stiffness || request.damping) {
    // One pass in duals seeded on q (directions 0 … n−1) and v (n … 2n−1): K and C.
    using D = Dual<2 * n>;
    Eigen::Matrix<D, n, 1> qd, vd, ad, rd;
    for (int i = 0; i < n; ++i) {
      qd(i) = D::variable(local_q(i), i);
      vd(i) = D::variable(local_v(i), n + i);
      ad(i) = D(local_a(i));
    }
    ale_residual<D, Dim>(parameters_, table_, qd, vd, ad, dynamic, g, rd, out.energy);
    for (int i = 0; i < n; ++i) {
      if (request.residual) out.residual(i) += rd(i).value;
      if (request.stiffness) out.stiffness.row(i) += rd(i).grad.template head<n>().transpose();
      if (request.damping) out.damping.row(i) += rd(i).grad.template tail<n>().transpose();
    }
  } else {
    Local r;
    ale_residual<double, Dim>(parameters_, table_, local_q, local_v, local_a, dynamic, g, r,
                              out.energy);
    if (request.residual) out.residual += r;
  }
  if (request.mass && dynamic)
    rancf::ale_mass_matrix<Dim>(parameters_.section.mass_per_length, table_,
                                nodal<double, Dim>(local_q.template head<4 * Dim>()),
                                local_q(n - 2), local_q(n - 1), out.mass);
  if (!dynamic) out.energy.kinetic = 0.0;
  if (request.energy && dynamic && parameters_.section.damping_coefficient > 0.0)
    add_dissipative_force<Dim>(parameters_, table_, nodal<double, Dim>(local_q.template head<4 * Dim>()),
                               local_q(n - 1) - local_q(n - 2), nodal<double, Dim>(local_v.template head<4 * Dim>()),
                               local_v(n - 2), local_v(n - 1), out.dissipative_force);
}

template class RancfCableElement<2>;
template class RancfCableElement<3>;
template class AleRancfCableElement<2>;
template class AleRancfCableElement<3>;

}  // namespace spar::core
