// The test model "rotational springs" (2D only), registered from outside the library: a linear
// 2D bond model of rotational springs. Per bond (n = xi/|xi|, t = e_z x n, L = |xi|) the strains
//   e_n = n . (u_j - u_i),   e_t = t . (u_j - u_i) - L (theta_i + theta_j) / 2,
//   e_r = theta_j - theta_i
// (all zero for a rigid motion) store E_b = 1/2 (k_n e_n^2 + k_t e_t^2 + k_r e_r^2) with
// k_n = c_n V_i V_j / L, k_t = c_t V_i V_j / L, k_r = c_r V_i V_j L. Used by
// tests/pd/micropolar_01 and tests/coupling/micropolar_coupling_01.
#ifndef perideal_tests_rotational_springs_h
#define perideal_tests_rotational_springs_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <perideal/pd/material_model.h>
#include <perideal/pd/particle_system.h>

#include <array>
#include <vector>

namespace perideal_tests
{
  template <int dim>
  class RotationalSprings : public perideal::MaterialModel<dim>
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Axial stiffness", "1e20", dealii::Patterns::Double(0.), "c_n [N/m^6]");
      prm.declare_entry("Shear stiffness", "5e19", dealii::Patterns::Double(0.), "c_t [N/m^6]");
      prm.declare_entry("Rotational stiffness",
                        "1e13",
                        dealii::Patterns::Double(0.),
                        "c_r [N/m^4]");
      prm.declare_entry("Radius of gyration",
                        "5e-4",
                        dealii::Patterns::Double(0.),
                        "r [m]: rotational inertia density rho r^2");
    }

    void
    parse_parameters(dealii::ParameterHandler &prm) override
    {
      c_n    = prm.get_double("Axial stiffness");
      c_t    = prm.get_double("Shear stiffness");
      c_r    = prm.get_double("Rotational stiffness");
      radius = prm.get_double("Radius of gyration");
    }

    perideal::FieldLayout
    field_layout() const override
    {
      return perideal::FieldLayout::displacement_and_rotation(dim);
    }

    std::vector<double>
    inertia_densities(const double density) const override
    {
      return {density, density, density * radius * radius};
    }

    void
    initialize(perideal::ParticleSystem<dim> &particles, const perideal::ModelContext &) override
    {
      const auto &bonds  = particles.bonds();
      const auto &volume = particles.volumes();
      const auto &x      = particles.positions();
      normal.resize(bonds.size());
      weight.resize(bonds.size());
      for (unsigned int i = 0; i < particles.n_owned(); ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            const unsigned int j  = bonds.neighbor[b];
            const double       L  = bonds.length[b];
            const double       VV = volume[i] * volume[j] * bonds.volume_factor(b);
            normal[b]             = (x[j] - x[i]) / L;
            weight[b]             = {c_n * VV / L, c_t * VV / L, c_r * VV * L};
          }
    }

    // The three rows of bond b of row i: entries (particle, component, coefficient).
    void
    rows(const perideal::ParticleSystem<dim>                          &particles,
         const unsigned int                                            i,
         const std::size_t                                             b,
         std::array<std::vector<perideal::LinearizedModel::Entry>, 3> &row) const
    {
      const unsigned int j = particles.bonds().neighbor[b];
      const double       L = particles.bonds().length[b];
      const auto        &n = normal[b];
      for (auto &r : row)
        r.clear();
      row[0] = {{i, 0, -n[0]}, {i, 1, -n[1]}, {j, 0, n[0]}, {j, 1, n[1]}};
      row[1] = {{i, 0, n[1]},
                {i, 1, -n[0]},
                {j, 0, -n[1]},
                {j, 1, n[0]},
                {i, 2, -0.5 * L},
                {j, 2, -0.5 * L}};
      row[2] = {{i, 2, -1.}, {j, 2, 1.}};
    }

    void
    compute_forces(perideal::ParticleSystem<dim>  &particles,
                   const perideal::ParticleVector &u,
                   perideal::ParticleVector       &force,
                   std::vector<double>            *energy_density,
                   const double) override
    {
      const auto        &bonds   = particles.bonds();
      const auto        &volume  = particles.volumes();
      const unsigned int n_owned = particles.n_owned();
      force                      = 0.;
      if (energy_density != nullptr)
        energy_density->assign(n_owned, 0.);
      std::array<std::vector<perideal::LinearizedModel::Entry>, 3> row;
      for (unsigned int i = 0; i < n_owned; ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            rows(particles, i, b, row);
            const unsigned int j = bonds.neighbor[b];
            for (unsigned int r = 0; r < 3; ++r)
              {
                double e = 0.;
                for (const auto &entry : row[r])
                  e += entry.coefficient * u.local_element(entry.particle * 3 + entry.component);
                for (const auto &entry : row[r])
                  if (entry.particle < n_owned)
                    force.local_element(entry.particle * 3 + entry.component) -=
                      weight[b][r] * e * entry.coefficient / volume[entry.particle];
                if (energy_density != nullptr)
                  {
                    const double half = 0.25 * weight[b][r] * e * e;
                    (*energy_density)[i] += half / volume[i];
                    if (j < n_owned)
                      (*energy_density)[j] += half / volume[j];
                  }
              }
          }
    }

    void
    stiffness_bound(const perideal::ParticleSystem<dim> &particles,
                    std::vector<double>                 &per_particle) const override
    {
      // Gershgorin from the rows: row r adds w |g_(p,c)| sum_q |g_q| / V_p to unknown (p, c).
      perideal::ParticleVector bound;
      particles.reinit_vector(bound, 3);
      std::array<std::vector<perideal::LinearizedModel::Entry>, 3> row;
      const auto                                                  &bonds = particles.bonds();
      for (unsigned int i = 0; i < particles.n_owned(); ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            rows(particles, i, b, row);
            for (unsigned int r = 0; r < 3; ++r)
              {
                double sum = 0.;
                for (const auto &entry : row[r])
                  sum += std::abs(entry.coefficient);
                for (const auto &entry : row[r])
                  bound.local_element(entry.particle * 3 + entry.component) +=
                    particles.bond_share(b) * weight[b][r] * std::abs(entry.coefficient) * sum /
                    particles.volumes()[entry.particle];
              }
          }
      bound.compress(dealii::VectorOperation::add);
      per_particle.resize(std::size_t(particles.n_owned()) * 3);
      for (std::size_t k = 0; k < per_particle.size(); ++k)
        per_particle[k] = bound.local_element(k);
    }

    void
    linearize(const perideal::ParticleSystem<dim> &particles,
              perideal::LinearizedModel           &linearized) const override
    {
      linearized.reinit(3, particles.n_owned());
      std::array<std::vector<perideal::LinearizedModel::Entry>, 3> row;
      const auto                                                  &bonds = particles.bonds();
      for (unsigned int i = 0; i < particles.n_owned(); ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            rows(particles, i, b, row);
            for (unsigned int r = 0; r < 3; ++r)
              linearized.add_row(weight[b][r] * particles.bond_share(b), row[r]);
          }
    }

    double
    critical_stretch(const double) const override
    {
      return std::numeric_limits<double>::infinity();
    }

    std::string
    summary() const override
    {
      return "rotational springs (test model)";
    }

  private:
    double                              c_n = 0., c_t = 0., c_r = 0., radius = 0.;
    std::vector<dealii::Tensor<1, dim>> normal;
    std::vector<std::array<double, 3>>  weight;
  };
} // namespace perideal_tests

PERIDEAL_REGISTER_PLUGIN(::perideal::MaterialModel<2>,
                         perideal_tests::RotationalSprings<2>,
                         "rotational springs",
                         "(test) linear micropolar bonds: axial, shear and rotational springs.")

#endif
