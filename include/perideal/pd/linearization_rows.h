// ---------------------------------------------------------------------
// PeriDeal: the rows of the strain operator that several models' linearizations share.
// ---------------------------------------------------------------------
#ifndef perideal_pd_linearization_rows_h
#define perideal_pd_linearization_rows_h

#include <perideal/pd/material_model.h>
#include <perideal/pd/particle_system.h>

#include <vector>

namespace perideal
{
  /**
   * @brief The rows of LinearizedModel that several models' linearize() emit: the linearized
   * extension of a bond, the slope of a scalar field, and the bond rows of a bond-based model.
   */
  namespace LinearizationRows
  {
    /**
     * @brief Append to @p row the entries of @p factor n_b . (u_j - u_i), the linearized
     * extension of bond @p b stored in the row of particle @p i (n_b = (x_j - x_i)/|xi|, the
     * same for both ends).
     */
    template <int dim>
    void
    add_extension(const ParticleSystem<dim>           &particles,
                  const unsigned int                   i,
                  const std::size_t                    b,
                  const double                         factor,
                  std::vector<LinearizedModel::Entry> &row)
    {
      const BondList    &bonds = particles.bonds();
      const auto        &x     = particles.positions();
      const unsigned int j     = bonds.neighbor[b];
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double n_d = (x[j][d] - x[i][d]) / bonds.length[b];
          row.push_back({i, d, -(factor * n_d)});
          row.push_back({j, d, factor * n_d});
        }
    }

    /**
     * @brief The bond rows of a bond-based model: for every bond b with stiffness
     * @p k[b] != 0 (N/m, per BondList entry), the row that @p add_row(i, b, row) appends (the
     * bond's linearized extension) with weight k_b times the bond's share and offset
     * @p offset[b] (its extension of no energy, a thermal extension; 0 for all without
     * @p offset); the stiffness scale of an owned particle is the sum of k_b over its bonds.
     */
    template <int dim, typename RowFunction>
    void
    add_bond_rows(const ParticleSystem<dim> &particles,
                  const std::vector<double> &k,
                  const RowFunction         &add_row,
                  LinearizedModel           &linearized,
                  const std::vector<double> *offset = nullptr)
    {
      const BondList                     &bonds   = particles.bonds();
      const unsigned int                  n_owned = particles.n_owned();
      std::vector<double>                &scale   = linearized.stiffness_scale();
      std::vector<LinearizedModel::Entry> row;
      for (unsigned int i = 0; i < n_owned; ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            const unsigned int j = bonds.neighbor[b];
            scale[i] += k[b];
            if (j < n_owned)
              scale[j] += k[b];
            if (k[b] != 0.)
              {
                row.clear();
                add_row(i, b, row);
                linearized.add_row(k[b] * particles.bond_share(b),
                                   row,
                                   offset != nullptr ? (*offset)[b] : 0.);
              }
          }
    }

    /**
     * @brief The stiffness k_b = @p coefficient[b] / |xi| of every intact bond (0 for broken
     * ones): the bond row weight of a bond-based model of pair coefficients @p coefficient
     * (bond_pair_coefficients()).
     */
    inline std::vector<double>
    intact_bond_stiffness(const BondList &bonds, const std::vector<double> &coefficient)
    {
      std::vector<double> k(bonds.size(), 0.);
      for (std::size_t b = 0; b < bonds.size(); ++b)
        if (bonds.intact[b])
          k[b] = coefficient[b] / bonds.length[b];
      return k;
    }

    /**
     * @brief The row w_j - w_i of bond b stored in the row of particle i: the bond slope of a
     * scalar field times |xi| (the antiplane models' bond-based energy).
     */
    inline auto
    slope_row(const BondList &bonds)
    {
      return [&bonds](const unsigned int                   i,
                      const std::size_t                    b,
                      std::vector<LinearizedModel::Entry> &row) {
        row.push_back({i, 0, -1.});
        row.push_back({bonds.neighbor[b], 0, 1.});
      };
    }

    /**
     * @brief The row n_b . (u_j - u_i) of bond b stored in the row of particle i: the
     * linearized extension of a displacement model.
     */
    template <int dim>
    auto
    extension_row(const ParticleSystem<dim> &particles)
    {
      return [&particles](const unsigned int                   i,
                          const std::size_t                    b,
                          std::vector<LinearizedModel::Entry> &row) {
        add_extension(particles, i, b, 1., row);
      };
    }
  } // namespace LinearizationRows
} // namespace perideal

#endif
