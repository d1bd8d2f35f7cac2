// ---------------------------------------------------------------------
// PeriDeal: the least-squares fit of FE dof values from the particle field.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <perideal/base/cell_list.h>
#include <perideal/coupling/interface_fit.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

#include <Eigen/QR>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  InterfaceFit<dim>::reinit(const ParticleSystem<dim> &particles,
                            const std::vector<bool>   &constrained,
                            const std::vector<Node>   &nodes,
                            const IndexSet            &owned,
                            const std::string         &blending_entry)
  {
    const MPI_Comm      comm    = particles.get_communicator();
    const double        delta   = particles.settings().horizon;
    const unsigned int  n_owned = particles.n_owned();
    const auto         &x       = particles.positions();
    std::vector<double> packed;
    for (const Node &node : nodes)
      {
        packed.push_back(node.dof);
        packed.push_back(node.component);
        for (unsigned int d = 0; d < dim; ++d)
          packed.push_back(node.location[d]);
      }

    std::vector<double> all;
    for (const auto &part : Utilities::MPI::all_gather(comm, packed))
      all.insert(all.end(), part.begin(), part.end());
    const unsigned int stride   = 2 + dim;
    const std::size_t  n_points = all.size() / stride;
    const auto         point_of = [&](const std::size_t p) {
      Point<dim> y;
      for (unsigned int d = 0; d < dim; ++d)
        y[d] = all[p * stride + 2 + d];
      return y;
    };
    CellList<dim> cells;
    cells.reinit(make_array_view(x.data(), x.data() + n_owned), delta);
    const double              none = std::numeric_limits<double>::max();
    std::vector<double>       distance(n_points, none), rank_index(n_points, none);
    std::vector<unsigned int> nearest(n_points, numbers::invalid_unsigned_int);
    for (std::size_t p = 0; p < n_points; ++p)
      {
        const Point<dim> y = point_of(p);
        cells.for_each_near(y, [&](const unsigned int i) {
          const double r = y.distance(x[i]);
          const auto   n = static_cast<double>(particles.invariant_index(i));
          if (r < distance[p] || (r == distance[p] && n < rank_index[p]))
            {
              distance[p]   = r;
              rank_index[p] = n;
              nearest[p]    = i;
            }
        });
      }
    std::vector<double> shortest(n_points), chosen(n_points);
    Utilities::MPI::min(distance, comm, shortest);
    for (std::size_t p = 0; p < n_points; ++p)
      if (distance[p] != shortest[p])
        rank_index[p] = none;
    Utilities::MPI::min(rank_index, comm, chosen);
    std::uint64_t n_far = 0;
    for (std::size_t p = 0; p < n_points; ++p)
      n_far += (shortest[p] > delta);
    AssertThrow(n_far == 0,
                ExcMessage(std::to_string(n_far) +
                           " FE dofs of cells that reach beta = 1 have no particle within a "
                           "horizon: the PD part (<Discretization/Body> where beta > 0) must "
                           "cover every FE cell that reaches beta = 1 (" +
                           blending_entry + ")."));

    // The families of the chosen particles (all bonds of the reference configuration).
    std::map<unsigned int, std::vector<unsigned int>> family;
    for (std::size_t p = 0; p < n_points; ++p)
      if (nearest[p] != numbers::invalid_unsigned_int && rank_index[p] == chosen[p])
        family[nearest[p]];
    const auto &bonds = particles.bonds();
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const unsigned int j = bonds.neighbor[b];
          if (const auto found = family.find(i); found != family.end())
            found->second.push_back(j);
          if (const auto found = family.find(j); found != family.end())
            found->second.push_back(i);
        }

    constexpr unsigned int n_quadratic = 1 + dim + dim * (dim + 1) / 2, n_linear = 1 + dim;
    dofs.clear();
    components.clear();
    start.assign(1, 0);
    particles_of.clear();
    weights.clear();
    IndexSet                              ghosts(owned.size());
    std::uint64_t                         n_in_layer = 0;
    Eigen::MatrixXd                       A;
    Eigen::VectorXd                       w;
    Eigen::HouseholderQR<Eigen::MatrixXd> qr;
    for (std::size_t p = 0; p < n_points; ++p)
      if (nearest[p] != numbers::invalid_unsigned_int && rank_index[p] == chosen[p])
        {
          const unsigned int i = nearest[p];
          n_in_layer += constrained[i];
          std::vector<unsigned int> members = family[i];
          members.push_back(i);
          const unsigned int n_basis = members.size() >= 2 * n_quadratic ? n_quadratic : n_linear;
          const Point<dim>   y       = point_of(p);
          // The fit matrix: row k holds the monomials a(r_k) of member k.
          A.resize(members.size(), n_basis);
          for (unsigned int k = 0; k < members.size(); ++k)
            {
              const Tensor<1, dim>            r = (x[members[k]] - y) / delta;
              std::array<double, n_quadratic> a;
              unsigned int                    m = 0;
              a[m++]                            = 1.;
              for (unsigned int d = 0; d < dim; ++d)
                a[m++] = r[d];
              for (unsigned int d = 0; d < dim; ++d)
                for (unsigned int e = d; e < dim; ++e)
                  a[m++] = r[d] * r[e];
              for (unsigned int n = 0; n < n_basis; ++n)
                A(k, n) = a[n];
            }
          // w = A (A^T A)^-1 e_0 = Q R^-T e_0 of the QR factorization A = Q R: the first row
          // of the pseudo-inverse, without forming the normal equations (whose condition number
          // is that of A squared).
          qr.compute(A);
          w.setZero(members.size());
          w(0) = 1.;
          qr.matrixQR()
            .topLeftCorner(n_basis, n_basis)
            .template triangularView<Eigen::Upper>()
            .transpose()
            .solveInPlace(w.head(n_basis));
          qr.householderQ().applyThisOnTheLeft(w);
          for (unsigned int k = 0; k < members.size(); ++k)
            {
              particles_of.push_back(members[k]);
              weights.push_back(w(k));
            }
          const auto dof = static_cast<types::global_dof_index>(all[p * stride]);
          dofs.push_back(dof);
          components.push_back(static_cast<unsigned int>(all[p * stride + 1]));
          start.push_back(particles_of.size());
          if (!owned.is_element(dof))
            ghosts.add_index(dof);
        }
    n_in_layer = Utilities::MPI::sum(n_in_layer, comm);
    AssertThrow(n_in_layer == 0,
                ExcMessage(blending_entry + ": " + std::to_string(n_in_layer) +
                           " FE dofs prescribed by the PD field (the nodes of cells that reach "
                           "beta = 1) lie nearest to particles of the PD volume constraint "
                           "(within a horizon of beta = 0), so the two parts would exchange no "
                           "information there. Widen the overlap 0 < beta < 1 to more than a "
                           "horizon plus an FE cell."));
    ghosts.compress();
    fitted.reinit(owned, ghosts, comm);
  }

  template <int dim>
  void
  InterfaceFit<dim>::evaluate(const ParticleVector            &u,
                              const unsigned int               n_components,
                              const std::vector<unsigned int> &local_dofs,
                              std::vector<double>             &values)
  {
    fitted = 0.;
    for (std::size_t k = 0; k < dofs.size(); ++k)
      {
        double value = 0.;
        for (unsigned int m = start[k]; m < start[k + 1]; ++m)
          value += weights[m] * u.local_element(particles_of[m] * n_components + components[k]);
        fitted(dofs[k]) = value;
      }
    fitted.compress(VectorOperation::add);
    values.resize(local_dofs.size());
    for (std::size_t j = 0; j < local_dofs.size(); ++j)
      values[j] = fitted.local_element(local_dofs[j]);
  }

  template class InterfaceFit<2>;
  template class InterfaceFit<3>;
} // namespace perideal
