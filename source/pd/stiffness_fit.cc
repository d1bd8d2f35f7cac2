// ---------------------------------------------------------------------
// PeriDeal: the stiffness fit, a surface correction that restores each particle's whole
// elasticity tensor.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <perideal/pd/stiffness_fit.h>
#include <perideal/pd/stiffness_fit_equations.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  std::string
  StiffnessFitReport::summary() const
  {
    std::ostringstream out;
    out << "stiffness fit: deviation of the particles' tensors from the interior's, largest "
        << largest_before << " -> " << largest_after << ", rms " << rms_before << " -> "
        << rms_after << "; bond factors " << smallest_factor << " ... " << largest_factor << " ("
        << held << " bonds at a bound), times " << interior_scale
        << " (the target's C_1111 over the lattice's)";
    return out.str();
  }

  namespace
  {
    /// The bounds of the factors: every bond keeps a positive, bounded stiffness.
    constexpr double smallest_factor = 0.2, largest_factor = 5.;
    /// rho relative to the mean diagonal of the normal equations.
    constexpr double relative_regularization = 1e-2;

    using stiffness_fit::BlockJacobi;
    using stiffness_fit::NormalEquations;
    using stiffness_fit::Voigt;

    /**
     * @brief The entries h_b of the bonds of @p particles (NormalEquations::table): by lattice
     * vector if the particles sit on an unperturbed lattice, else per bond.
     */
    template <int dim>
    void
    set_bond_tensors(const ParticleSystem<dim>   &particles,
                     const BondStiffnessLaw<dim> &law,
                     const double                 unit,
                     NormalEquations<dim>        &equations)
    {
      using V                        = Voigt<dim>;
      constexpr unsigned int m       = V::unique;
      const BondList        &bonds   = particles.bonds();
      const auto            &x       = particles.positions();
      const auto            &volume  = particles.volumes();
      const unsigned int     n_owned = particles.n_owned();
      const double           dx      = particles.lattice().spacing();
      // The lattice vectors of the bonds, numbered in a box of (2 reach + 1)^dim vectors.
      const long       reach = static_cast<long>(std::ceil(particles.search_radius() / dx)) + 1;
      const long       width = 2 * reach + 1;
      std::vector<int> number;
      bool             by_vector = particles.lattice().offset_bound() == 0. && dx > 0.;
      if (by_vector)
        {
          std::size_t size = 1;
          for (unsigned int d = 0; d < dim; ++d)
            size *= width;
          number.assign(size, -1);
          equations.vector_of.resize(bonds.size());
          equations.scales.resize(bonds.size());
        }
      for (unsigned int i = 0; i < n_owned && by_vector; ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            const unsigned int j  = bonds.neighbor[b];
            const auto         xi = x[j] - x[i];
            // The bond's lattice vector n (xi = n dx up to round-off).
            std::size_t    slot = 0, stride = 1;
            Tensor<1, dim> lattice_vector;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const long n = std::lround(xi[d] / dx);
                if (std::abs(xi[d] - n * dx) > 1e-6 * dx || std::abs(n) > reach)
                  by_vector = false;
                slot += (n + reach) * stride;
                stride *= width;
                lattice_vector[d] = n * dx;
              }
            if (!by_vector)
              break;
            if (number[slot] < 0)
              {
                if (equations.table.size() / m > std::numeric_limits<std::uint16_t>::max())
                  {
                    by_vector = false;
                    break;
                  }
                double axial, shear;
                law(lattice_vector, axial, shear);
                number[slot] = equations.table.size() / m;
                const auto h = V::bond_tensor(lattice_vector / lattice_vector.norm(), axial, shear);
                equations.table.insert(equations.table.end(), h.begin(), h.end());
              }
            equations.vector_of[b] = number[slot];
            equations.scales[b]    = bonds.volume_factor(b) * volume[i] * volume[j] / unit;
          }
      // The same choice on every rank (the same round-off whatever the rank count).
      by_vector = Utilities::MPI::min(by_vector ? 1 : 0, particles.get_communicator()) == 1;
      equations.by_vector = by_vector;
      if (by_vector)
        {
          equations.set_classes();
          return;
        }
      equations.vector_of.clear();
      equations.scales.clear();
      equations.table.assign(bonds.size() * m, 0.);
      for (unsigned int i = 0; i < n_owned; ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            double               axial, shear;
            const Tensor<1, dim> xi = x[bonds.neighbor[b]] - x[i];
            law(xi, axial, shear);
            const double k = bonds.volume_factor(b) * volume[i] * volume[bonds.neighbor[b]] / unit;
            const auto   h = V::bond_tensor(xi / bonds.length[b], k * axial, k * shear);
            std::copy(h.begin(), h.end(), equations.table.begin() + std::size_t(b) * m);
          }
    }
  } // namespace

  template <int dim>
  StiffnessFitReport
  apply_stiffness_fit(ParticleSystem<dim>         &particles,
                      const BondStiffnessLaw<dim> &law,
                      const double                 modulus)
  {
    using V                        = Voigt<dim>;
    constexpr unsigned int m       = V::unique;
    BondList              &bonds   = particles.bonds();
    const auto            &volume  = particles.volumes();
    const unsigned int     n_owned = particles.n_owned();
    const MPI_Comm         comm    = particles.get_communicator();
    StiffnessFitReport     report;
    // A coupled problem may leave the region without particles.
    if (particles.n_global() == 0)
      return report;

    // The interior's tensor per unit volume of the particle, from the lattice family.
    std::vector<Tensor<1, dim>> family;
    std::vector<double>         family_weight;
    particles.lattice_family(family, family_weight);
    typename V::Entries interior{};
    for (unsigned int f = 0; f < family.size(); ++f)
      {
        const double length = family[f].norm();
        double       axial, shear;
        law(family[f], axial, shear);
        const auto h =
          V::bond_tensor(family[f] / length, family_weight[f] * axial, family_weight[f] * shear);
        for (unsigned int k = 0; k < m; ++k)
          interior[k] += h[k];
      }
    // Scale: the interior's largest entry times the largest volume, so that the multipliers
    // are of the order of the relative deviations.
    double largest_volume = 0.;
    for (unsigned int i = 0; i < n_owned; ++i)
      largest_volume = std::max(largest_volume, volume[i]);
    largest_volume       = Utilities::MPI::max(largest_volume, comm);
    double largest_entry = 0.;
    for (const double d : interior)
      largest_entry = std::max(largest_entry, std::abs(d));
    const double unit = largest_entry * largest_volume;
    AssertThrow(interior[0] > 0., ExcInternalError());

    NormalEquations<dim> equations(particles);
    set_bond_tensors(particles, law, unit, equations);

    // The right-hand side, the interior's D V_i minus the particles' with the factors without
    // multipliers; with @p lambda, the particles' deviation after the fit. Returns the largest
    // and the root-mean-square deviation relative to the interior's largest entry.
    ParticleVector rhs, lambda, sums;
    particles.reinit_vector(rhs, m);
    particles.reinit_vector(lambda, m);
    particles.reinit_vector(sums, m);
    const auto deviation = [&](const ParticleVector *multipliers) {
      sums = 0.;
      equations.add_bond_sums(sums, NormalEquations<dim>::Sum::tensor, nullptr);
      if (multipliers)
        equations.add_bond_sums(sums, NormalEquations<dim>::Sum::change, multipliers);
      double largest = 0., squares = 0.;
      for (unsigned int i = 0; i < n_owned; ++i)
        for (unsigned int k = 0; k < m; ++k)
          {
            const double d = interior[k] * volume[i] / unit - sums.local_element(i * m + k);
            rhs.local_element(i * m + k) = d;
            const double relative        = d * largest_volume / volume[i];
            largest                      = std::max(largest, std::abs(relative));
            squares += relative * relative;
          }
      const double n = static_cast<double>(particles.n_global()) * m;
      return std::make_pair(Utilities::MPI::max(largest, comm),
                            std::sqrt(Utilities::MPI::sum(squares, comm) / n));
    };
    report.interior_scale                              = modulus / interior[0];
    std::tie(report.largest_before, report.rms_before) = deviation(nullptr);

    // Rounds: CG on the normal equations of the free bonds (block-Jacobi preconditioner); a
    // free bond whose factor leaves the bounds is held at the bound it crossed, and the others
    // are fitted again, until every factor is within the bounds. A round solves to 1e-6 of the
    // right-hand side first, enough to find the bonds that leave the bounds; only a round that
    // finds none goes on to the final 1e-10 (and checks the bounds again).
    {
      ParticleVector diagonal;
      particles.reinit_vector(diagonal, m);
      equations.add_bond_sums(diagonal, NormalEquations<dim>::Sum::squares, nullptr);
      equations.regularization = relative_regularization * diagonal.mean_value();
    }
    BlockJacobi<dim>          preconditioner;
    std::vector<std::uint8_t> changed;
    bool                      final_accuracy = false;
    for (unsigned int round = 0;; ++round)
      {
        AssertThrow(round < 100, ExcMessage("The stiffness fit did not settle in 100 rounds."));
        if (round == 0 || !final_accuracy)
          {
            if (round > 0)
              deviation(nullptr);
            preconditioner.reinit(equations, round == 0 ? nullptr : &changed);
            equations.sort_free_bonds();
          }
        // Warm start: each round begins from the last round's multipliers.
        const double             target = 1e-10 * rhs.l2_norm();
        SolverControl            control(10000, final_accuracy ? target : 1e4 * target);
        SolverCG<ParticleVector> cg(control);
        cg.solve(equations, lambda, rhs, preconditioner);

        lambda.update_ghost_values();
        changed.assign(n_owned, 0);
        unsigned int n_held = 0;
        for (unsigned int i = 0; i < n_owned; ++i)
          for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
            if (equations.free[b])
              {
                const double g = 1. + equations.change(i, b, lambda);
                if (g < smallest_factor || g > largest_factor)
                  {
                    equations.free[b]  = 0;
                    equations.fixed[b] = g < smallest_factor ? smallest_factor : largest_factor;
                    changed[i]         = 1;
                    if (bonds.neighbor[b] < n_owned)
                      changed[bonds.neighbor[b]] = 1;
                    ++n_held;
                  }
              }
        lambda.zero_out_ghost_values();
        if (Utilities::MPI::sum(n_held, comm) > 0)
          final_accuracy = false;
        else if (final_accuracy)
          break;
        else
          final_accuracy = true;
      }
    lambda.update_ghost_values();

    report.smallest_factor = std::numeric_limits<double>::max();
    report.largest_factor  = -std::numeric_limits<double>::max();
    unsigned long held     = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          bonds.surface_factor[b] =
            equations.free[b] ? 1. + equations.change(i, b, lambda) : equations.fixed[b];
          report.smallest_factor = std::min(report.smallest_factor, bonds.surface_factor[b]);
          report.largest_factor  = std::max(report.largest_factor, bonds.surface_factor[b]);
          // Twice, so that a bond to a ghost (a row on both ranks) counts once in the sum.
          if (!equations.free[b])
            held += particles.neighbor_is_owned(b) ? 2 : 1;
        }
    report.held            = Utilities::MPI::sum(held, comm) / 2;
    report.smallest_factor = Utilities::MPI::min(report.smallest_factor, comm);
    report.largest_factor  = Utilities::MPI::max(report.largest_factor, comm);
    std::tie(report.largest_after, report.rms_after) = deviation(&lambda);
    lambda.zero_out_ghost_values();
    for (double &g : bonds.surface_factor)
      g *= report.interior_scale;
    return report;
  }

  template StiffnessFitReport
  apply_stiffness_fit<2>(ParticleSystem<2> &, const BondStiffnessLaw<2> &, double);
  template StiffnessFitReport
  apply_stiffness_fit<3>(ParticleSystem<3> &, const BondStiffnessLaw<3> &, double);
} // namespace perideal
