// The stiffness fit (<Discretization/Surface correction method> = stiffness fit,
// apply_stiffness_fit(), doc/theory/models.md "Surface correction: the stiffness fit") against
// the energy method, on a square of 20 x 20 particles (delta = 3.015 dx, book partial volumes,
// plane stress) and a cube of 11^3:
//  - each particle's elasticity tensor D_i from the energy densities of homogeneous strains
//    (Voigt: e_11, e_22, e_11 + e_22, 2 e_12, e_11 + 2 e_12, e_22 + 2 e_12 in 2D; e_11, e_11 +
//    e_22, 2 e_23 in 3D; rotations 0, the fields' rotation), compared entry by entry with the
//    interior's (the mean over the particles more than a horizon from every face, all equal);
//  - the largest deviation relative to D_11, over the particles within a horizon of one face
//    only ("faces") and of two or more ("corners"), for PMB and for Timoshenko bonds (lattice
//    calibration, nu = 0.1 and 0.3 in 2D, 0.2 in 3D).
// Checks: with the fit, the tensors at the faces at least 10 times and in the interior at least
// 5 times closer to the interior's lattice tensor than with the energy method, which misses them
// by 27-32 % at the faces and by 6-11 % in the interior, where its factors averaged over the
// bonds' ends reach (measured: 0.8-2.2 % and 0.2-1.3 % with the fit). The fit is a least-squares
// compromise with rho = 1e-2 (doc/theory/models.md), exact nowhere; the corners cannot be fitted
// with positive bonds and stay 8-17 % off (printed). Every bond factor in [0.2, 5] times the
// interior's (C_1111 of PMB's target over its lattice's: 1.14; 1 for Timoshenko bonds). A model
// without the fit refuses it: pd/bad_input_01. 1 and 2 MPI ranks, the same numbers.

#include <perideal/pd/bond_based.h>
#include <perideal/pd/timoshenko_bond_based.h>

#include "../tests.h"
#include "pd_tests.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
  using namespace dealii;
  using pd_tests::ok;
  using perideal::PartialVolume;
  using perideal::ParticleVector;
  using perideal::PlanarAssumption;
  const MPI_Comm comm = MPI_COMM_WORLD;
  const double   inf  = std::numeric_limits<double>::infinity();

  // A strain in Voigt notation (e_11, e_22, 2 e_12) or (e_11, e_22, e_33, 2 e_23, 2 e_13,
  // 2 e_12).
  template <int dim>
  using Strain = std::array<double, dim == 2 ? 3 : 6>;

  // The particles' energy densities under the homogeneous strain e (rotations 0).
  template <int dim>
  std::vector<double>
  energy_densities(perideal::ParticleSystem<dim> &ps,
                   perideal::MaterialModel<dim>  &model,
                   const Strain<dim>             &e)
  {
    const unsigned int     nc = model.field_layout().n_components();
    Tensor<2, dim>         strain;
    constexpr unsigned int nv   = dim == 2 ? 3 : 6;
    const unsigned int     p[6] = {0, 1, 2, 1, 0, 0}, q[6] = {0, 1, 2, 2, 2, 1};
    for (unsigned int k = 0; k < nv; ++k)
      {
        const unsigned int a = dim == 2 && k == 2 ? 0 : p[k], b = dim == 2 && k == 2 ? 1 : q[k];
        const double       value = (a == b ? 1. : 0.5) * e[k];
        strain[a][b] += value;
        if (a != b)
          strain[b][a] += value;
      }
    ParticleVector u, f;
    ps.reinit_vector(u, nc);
    ps.reinit_vector(f, nc);
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      {
        const Tensor<1, dim> v = strain * ps.positions()[i];
        for (unsigned int d = 0; d < dim; ++d)
          u.local_element(i * nc + d) = v[d];
      }
    std::vector<double> w;
    model.compute_forces(ps, u, f, &w, inf);
    return w;
  }

  // Which part of the body particle i is in: 0 interior, 1 within a horizon of one face,
  // 2 of two or more.
  template <int dim>
  unsigned int
  zone(const pd_tests::Body<dim> &body, const unsigned int i)
  {
    unsigned int near = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const int k = static_cast<int>(std::lround(body.ps.positions()[i][d] / body.dx - 0.5));
        if (std::min(k, body.n - 1 - k) * body.dx < body.delta - 0.5 * body.dx)
          ++near;
      }
    return std::min(near, 2u);
  }

  // The entries of D_i checked: (D_11, D_22, D_12, D_66, D_16, D_26) in 2D, (D_11, D_12, D_44)
  // in 3D, from energy densities (W = e.D.e / 2).
  template <int dim>
  std::vector<std::vector<double>>
  tensors(pd_tests::Body<dim> &body, perideal::MaterialModel<dim> &model)
  {
    const double s = 1e-6;
    const auto   W = [&](const Strain<dim> &e) { return energy_densities<dim>(body.ps, model, e); };
    std::vector<std::vector<double>> D(body.ps.n_owned());
    if constexpr (dim == 2)
      {
        const auto w1 = W({{s, 0, 0}}), w2 = W({{0, s, 0}}), w12 = W({{s, s, 0}}),
                   w3 = W({{0, 0, s}}), w13 = W({{s, 0, s}}), w23 = W({{0, s, s}});
        for (unsigned int i = 0; i < D.size(); ++i)
          {
            const double d11 = 2. * w1[i] / (s * s), d22 = 2. * w2[i] / (s * s),
                         d66 = 2. * w3[i] / (s * s);
            D[i]             = {d11,
                                d22,
                                (2. * w12[i] / (s * s) - d11 - d22) / 2.,
                                d66,
                                (2. * w13[i] / (s * s) - d11 - d66) / 2.,
                                (2. * w23[i] / (s * s) - d22 - d66) / 2.};
          }
      }
    else
      {
        const auto w1 = W({{s, 0, 0, 0, 0, 0}}), w12 = W({{s, s, 0, 0, 0, 0}}),
                   w2 = W({{0, s, 0, 0, 0, 0}}), w4 = W({{0, 0, 0, s, 0, 0}});
        for (unsigned int i = 0; i < D.size(); ++i)
          {
            const double d11 = 2. * w1[i] / (s * s), d22 = 2. * w2[i] / (s * s);
            D[i] = {d11, (2. * w12[i] / (s * s) - d11 - d22) / 2., 2. * w4[i] / (s * s)};
          }
      }
    return D;
  }

  struct Deviation
  {
    // The largest |D_i - D| / D_11 per zone (interior, faces, corners).
    std::array<double, 3> largest{};
  };

  template <int dim>
  Deviation
  deviation(pd_tests::Body<dim> &body, perideal::MaterialModel<dim> &model)
  {
    const auto          D = tensors<dim>(body, model);
    const unsigned int  m = D.empty() ? (dim == 2 ? 6 : 3) : D[0].size();
    std::vector<double> interior(m, 0.);
    double              count = 0.;
    for (unsigned int i = 0; i < D.size(); ++i)
      if (zone(body, i) == 0)
        {
          for (unsigned int k = 0; k < m; ++k)
            interior[k] += D[i][k];
          count += 1.;
        }
    count = Utilities::MPI::sum(count, comm);
    for (double &d : interior)
      d = Utilities::MPI::sum(d, comm) / count;
    Deviation result;
    for (unsigned int i = 0; i < D.size(); ++i)
      for (unsigned int k = 0; k < m; ++k)
        {
          double &largest = result.largest[zone(body, i)];
          largest         = std::max(largest, std::abs(D[i][k] - interior[k]) / interior[0]);
        }
    for (double &d : result.largest)
      d = Utilities::MPI::max(d, comm);
    return result;
  }

  // The range of the bond factors over the ranks. PMB frees the factors after its set-up and
  // keeps k = c G chi V_i V_j: G from k there.
  template <int dim>
  std::pair<double, double>
  factor_range(const perideal::ParticleSystem<dim> &ps, const perideal::MaterialModel<dim> &model)
  {
    const auto &bonds  = ps.bonds();
    const auto &volume = ps.volumes();
    const auto *pmb    = dynamic_cast<const perideal::BondBased<dim> *>(&model);
    double      lo = inf, hi = -inf;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const double x = pmb != nullptr ? pmb->pair_coefficient(ps, i, b) /
                                              (pmb->micromodulus() * bonds.volume_factor(b) *
                                               volume[i] * volume[bonds.neighbor[b]]) :
                                            bonds.surface_factor[b];
          lo             = std::min(lo, x);
          hi             = std::max(hi, x);
        }
    return {Utilities::MPI::min(lo, comm), Utilities::MPI::max(hi, comm)};
  }

  template <int dim>
  std::unique_ptr<perideal::MaterialModel<dim>>
  make_model(const std::string &name, const double nu)
  {
    if (name == "bond based")
      {
        auto model = std::make_unique<perideal::BondBased<dim>>();
        pd_tests::parse_model(*model, {{"Young's modulus", "2e11"}});
        return model;
      }
    auto model = std::make_unique<perideal::TimoshenkoBondBased<dim>>();
    pd_tests::parse_model(*model,
                          {{"Young's modulus", "2e11"},
                           {"Poisson's ratio", std::to_string(nu)},
                           {"Calibration", "lattice"}});
    return model;
  }

  template <int dim>
  void
  compare(const std::string &name, const double nu)
  {
    deallog << name << (name == "bond based" ? "" : ", nu = " + std::to_string(nu).substr(0, 4))
            << " (" << dim << "D):" << std::endl;
    Deviation energy;
    for (const bool fit : {false, true})
      {
        pd_tests::Body<dim> body(dim == 2 ? 20 : 11, 1e-3, 3.015, PartialVolume::book, 0.01);
        auto                model   = make_model<dim>(name, nu);
        auto                context = pd_tests::model_context(body.delta,
                                               0.01,
                                               dim == 2 ? PlanarAssumption::plane_stress :
                                                                         PlanarAssumption::three_dimensional,
                                               true);
        context.stiffness_fit       = fit;
        model->initialize(body.ps, context);
        const auto d     = deviation<dim>(body, *model);
        const auto range = factor_range(body.ps, *model);
        deallog << "  " << (fit ? "stiffness fit" : "energy method")
                << ": largest |D_i - D| / D_11 interior " << d.largest[0] << ", faces "
                << d.largest[1] << ", corners " << d.largest[2] << "; factors " << range.first
                << " ... " << range.second << std::endl;
        if (!fit)
          energy = d;
        else
          {
            deallog << "  faces 10 times and interior 5 times closer than the energy method: "
                    << ok(10. * d.largest[1] < energy.largest[1] &&
                          5. * d.largest[0] < energy.largest[0])
                    << "; factors positive, within the bounds' ratio 25: "
                    << ok(range.first > 0. && range.second <= 25. * range.first * (1. + 1e-12))
                    << std::endl;
          }
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog << std::setprecision(3);
  // The conjugate-gradient solver of the fit logs its iterations one level down.
  deallog.depth_file(1);

  compare<2>("bond based", 1. / 3.);
  compare<2>("timoshenko bond based", 0.1);
  compare<2>("timoshenko bond based", 0.3);
  compare<3>("timoshenko bond based", 0.2);
}
