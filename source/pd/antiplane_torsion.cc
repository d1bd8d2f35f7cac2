// ---------------------------------------------------------------------
// PeriDeal: what the antiplane models need for Saint-Venant torsion (the warping as unknown).
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/antiplane_torsion.h>

#include <algorithm>
#include <limits>

namespace perideal
{
  namespace AntiplaneTorsion
  {
    using namespace dealii;

    template <int dim>
    void
    check_section(const ParticleSystem<dim> &particles, const Torsion &torsion)
    {
      const MPI_Comm comm = particles.get_communicator();
      const double   dx = particles.settings().spacing, delta = particles.settings().horizon;
      const auto    &x = particles.positions();
      for (unsigned int d = 0; d < 2; ++d)
        {
          double low = std::numeric_limits<double>::max(), high = -low;
          for (unsigned int i = 0; i < particles.n_owned(); ++i)
            {
              low  = std::min(low, x[i][d]);
              high = std::max(high, x[i][d]);
            }
          // The section's extent: the lattice cells of the particles.
          low              = Utilities::MPI::min(low, comm) - 0.5 * dx;
          high             = Utilities::MPI::max(high, comm) + 0.5 * dx;
          const char *axis = d == 0 ? "x" : "y";
          AssertThrow(high - low >= 2. * delta,
                      ExcMessage(std::string("Torsion: the section is ") +
                                 ParameterUtilities::format_number(high - low) + " m wide in " +
                                 axis + ", less than two horizons (delta = " +
                                 ParameterUtilities::format_number(delta) +
                                 " m): the particles near one face would see the other. "
                                 "Accepted: <Discretization/Horizon factor> times "
                                 "<Discretization/Lattice spacing> at most half the section's "
                                 "width (refine the lattice)."));
          const double center = torsion.axis()[d];
          AssertThrow(center >= low && center <= high,
                      ExcMessage("The parameter " + torsion.axis_entry() + " has " + axis + " = " +
                                 ParameterUtilities::format_number(center) +
                                 ", outside the section (" + axis + " in [" +
                                 ParameterUtilities::format_number(low) + ", " +
                                 ParameterUtilities::format_number(high) +
                                 "]); accepted are points of the section (the twist axis must "
                                 "pierce the bar's cross-section)."));
        }
    }

    template <int dim>
    std::vector<double>
    twist_fields(const ParticleSystem<dim> &particles, const Torsion &torsion)
    {
      const auto         &x = particles.positions();
      std::vector<double> fields(2 * x.size());
      for (unsigned int i = 0; i < x.size(); ++i)
        {
          fields[2 * i]     = torsion.twist() * (x[i][0] - torsion.axis()[0]);
          fields[2 * i + 1] = torsion.twist() * (x[i][1] - torsion.axis()[1]);
        }
      return fields;
    }

    template <int dim>
    void
    scalar_gradient(const ParticleSystem<dim>   &particles,
                    const ParticleVector        &w,
                    std::vector<Tensor<1, dim>> &gradient)
    {
      const unsigned int          n_owned = particles.n_owned();
      const auto                 &bonds   = particles.bonds();
      const auto                 &x       = particles.positions();
      const auto                 &volume  = particles.volumes();
      std::vector<Tensor<2, dim>> shape(n_owned);
      std::vector<Tensor<1, dim>> moment(n_owned);
      for (unsigned int i = 0; i < n_owned; ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            if (bonds.intact[b] == 0)
              continue;
            const unsigned int   j    = bonds.neighbor[b];
            const Tensor<1, dim> xi   = x[j] - x[i];
            const Tensor<2, dim> xixi = outer_product(xi, xi);
            const Tensor<1, dim> dw   = xi * (w.local_element(j) - w.local_element(i));
            const double         beta = bonds.volume_factor[b];
            shape[i] += beta * volume[j] * xixi;
            moment[i] += beta * volume[j] * dw;
            // The other end sees -xi and -(w_j - w_i): the same products.
            if (particles.neighbor_is_owned(b))
              {
                shape[j] += beta * volume[i] * xixi;
                moment[j] += beta * volume[i] * dw;
              }
          }
      gradient.assign(n_owned, Tensor<1, dim>());
      for (unsigned int i = 0; i < n_owned; ++i)
        if (std::abs(determinant(shape[i])) > 1e-12 * std::pow(trace(shape[i]), dim))
          gradient[i] = invert(shape[i]) * moment[i];
    }

    template <int dim>
    void
    shear_stresses(const ParticleSystem<dim>   &particles,
                   const ParticleVector        &w,
                   const Torsion               &torsion,
                   const double                 shear_modulus,
                   std::vector<Tensor<1, dim>> &tau)
    {
      scalar_gradient(particles, w, tau);
      const auto &x = particles.positions();
      for (unsigned int i = 0; i < tau.size(); ++i)
        tau[i] = shear_modulus * (tau[i] + torsion.twist_strain(x[i]));
    }

    std::vector<std::string>
    integral_names()
    {
      return {"torque", "torsion_energy"};
    }

    template <int dim>
    std::vector<double>
    section_integrals(const ParticleSystem<dim> &particles,
                      const ParticleVector      &w,
                      const Torsion             &torsion,
                      const double               shear_modulus,
                      const double               strain_energy)
    {
      std::vector<Tensor<1, dim>> tau;
      shear_stresses(particles, w, torsion, shear_modulus, tau);
      const auto  &x      = particles.positions();
      const auto  &volume = particles.volumes();
      const auto  &weight = particles.energy_weights();
      const double h      = particles.settings().thickness;
      double       torque = 0.;
      for (unsigned int i = 0; i < particles.n_owned(); ++i)
        torque += weight[i] * torsion.torque_density(x[i], tau[i]) * volume[i] / h;
      return {Utilities::MPI::sum(torque, particles.get_communicator()), strain_energy / h};
    }

#define PERIDEAL_INSTANTIATE(dim)                                                           \
  template void                check_section(const ParticleSystem<dim> &, const Torsion &); \
  template std::vector<double> twist_fields(const ParticleSystem<dim> &, const Torsion &);  \
  template void                scalar_gradient(const ParticleSystem<dim> &,                 \
                                               const ParticleVector &,                      \
                                               std::vector<Tensor<1, dim>> &);              \
  template void                shear_stresses(const ParticleSystem<dim> &,                  \
                                              const ParticleVector &,                       \
                                              const Torsion &,                              \
                                              const double,                                 \
                                              std::vector<Tensor<1, dim>> &);               \
  template std::vector<double> section_integrals(const ParticleSystem<dim> &,               \
                                                 const ParticleVector &,                    \
                                                 const Torsion &,                           \
                                                 const double,                              \
                                                 const double);
    PERIDEAL_INSTANTIATE(2)
    PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
  } // namespace AntiplaneTorsion
} // namespace perideal
