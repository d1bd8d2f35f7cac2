// ---------------------------------------------------------------------
// PeriDeal: the assembly of the finite-element region: the weighted stiffness (the physics'
// bilinear form times 1 - beta, thickness and JxW, and the h int phi_i phi_j of convection
// faces), the lumped mass (Gauss-Lobatto nodal quadrature), the load of the body force, the
// physics' own load (the twist of torsion) and the load conditions (convection: h T_inf), and
// what is computed from the stiffness: the stable explicit step, its row sums and the strain
// energy.
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <perideal/base/setup_times.h>
#include <perideal/fem/fe_region.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  FERegion<dim>::quadrature_weights(const FEValuesBase<dim> &fe_values,
                                    std::vector<double>     &weights) const
  {
    weights.resize(fe_values.n_quadrature_points);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      weights[q] = weight(fe_values.quadrature_point(q)) * thickness * fe_values.JxW(q);
  }

  template <int dim>
  void
  FERegion<dim>::assemble_matrices()
  {
    const SetupTimes::Scope time(SetupStage::fe_assembly);

    const auto   &fe = fe_collection[0];
    FEValues<dim> fe_values(fe,
                            QGauss<dim>(degree + 1),
                            update_gradients | update_quadrature_points | update_JxW_values);
    // Nodal (Gauss-Lobatto) quadrature: a diagonal, positive mass for every degree.
    FEValues<dim> nodal_values(fe,
                               QGaussLobatto<dim>(degree + 1),
                               update_values | update_quadrature_points | update_JxW_values);
    // Convection (Robin) faces: h int phi_i phi_j ds in the stiffness.
    FEFaceValues<dim>                    face_values(fe,
                                  QGauss<dim - 1>(degree + 1),
                                  update_values | update_quadrature_points | update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    dealii::Vector<double>               cell_mass(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<double>                  weights;
    // The lumped mass of the field: rho (inertia), or rho c (heat capacity) for a temperature.
    const double mass_density = density * physics_model->mass_factor();
    stiffness                 = 0.;
    mass                      = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0)
        {
          fe_values.reinit(cell);
          quadrature_weights(fe_values, weights);
          cell_matrix = 0.;
          physics_model->add_cell_stiffness(fe_values, cell->material_id(), weights, cell_matrix);
          if (cell->at_boundary())
            add_convection_stiffness(cell, face_values, cell_matrix);
          nodal_values.reinit(cell);
          cell_mass = 0.;
          for (const unsigned int q : nodal_values.quadrature_point_indices())
            {
              const double w = weight(nodal_values.quadrature_point(q)) * thickness * mass_density *
                               nodal_values.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                cell_mass(i) += nodal_values.shape_value(i, q) * w;
            }
          cell->get_dof_indices(dofs);
          hanging_constraints.distribute_local_to_global(cell_matrix, dofs, stiffness);
          hanging_constraints.distribute_local_to_global(cell_mass, dofs, mass);
        }
    stiffness.compress(VectorOperation::add);
    mass.compress(VectorOperation::add);
  }

  template <int dim>
  void
  FERegion<dim>::add_convection_stiffness(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    FEFaceValues<dim>                                    &face_values,
    FullMatrix<double>                                   &cell_matrix) const
  {
    std::vector<double> weights;
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        for (const auto &c : condition_list)
          if (c.convection && c.boundary_ids.count(cell->face(f)->boundary_id()) > 0)
            {
              face_values.reinit(cell, f);
              quadrature_weights(face_values, weights);
              for (const unsigned int q : face_values.quadrature_point_indices())
                {
                  const double w = c.convection->coefficient * weights[q];
                  for (unsigned int i = 0; i < face_values.dofs_per_cell; ++i)
                    for (unsigned int j = 0; j < face_values.dofs_per_cell; ++j)
                      cell_matrix(i, j) +=
                        face_values.shape_value(i, q) * face_values.shape_value(j, q) * w;
                }
            }
  }

  template <int dim>
  void
  FERegion<dim>::assemble_cell_load(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                    const double                                          time,
                                    FEValues<dim>                                        &fe_values,
                                    FEFaceValues<dim>      &fe_face_values,
                                    dealii::Vector<double> &cell_rhs) const
  {
    const unsigned int n  = fe_values.dofs_per_cell;
    const auto        &fe = fe_values.get_fe();
    cell_rhs              = 0.;
    std::vector<double>    weights;
    dealii::Vector<double> value(layout.n_components());
    if (body_force || physics_model->has_cell_load())
      quadrature_weights(fe_values, weights);
    if (body_force)
      {
        body_force->set_time(time);
        value.reinit(body_force->n_components);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const double w = weights[q];
            if (w == 0.)
              continue;
            body_force->vector_value(fe_values.quadrature_point(q), value);
            for (unsigned int i = 0; i < n; ++i)
              {
                const unsigned int c = fe.system_to_component_index(i).first;
                cell_rhs(i) += value(c) * fe_values.shape_value(i, q) * w;
              }
          }
      }
    if (physics_model->has_cell_load())
      physics_model->add_cell_load(fe_values, cell->material_id(), weights, cell_rhs);
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        {
          const auto id = cell->face(f)->boundary_id();
          for (const auto &c : condition_list)
            if (c.type == Quantity::load && c.boundary_ids.count(id) > 0)
              {
                fe_face_values.reinit(cell, f);
                // A convection's load is h T_inf (its h T is in the stiffness).
                const auto  &function = c.convection ? c.convection->ambient : c.function;
                const double factor   = c.convection ? c.convection->coefficient : 1.;
                function->set_time(time);
                quadrature_weights(fe_face_values, weights);
                value.reinit(function->n_components);
                for (const unsigned int q : fe_face_values.quadrature_point_indices())
                  {
                    const double w = factor * weights[q];
                    function->vector_value(fe_face_values.quadrature_point(q), value);
                    for (unsigned int i = 0; i < n; ++i)
                      {
                        const unsigned int comp = fe.system_to_component_index(i).first;
                        cell_rhs(i) += value(comp) * fe_face_values.shape_value(i, q) * w;
                      }
                  }
              }
        }
  }

  template <int dim>
  void
  FERegion<dim>::assemble_load(const double time, FEVector &f) const
  {
    const bool has_load = std::any_of(condition_list.begin(),
                                      condition_list.end(),
                                      [](const Condition &c) { return c.type == Quantity::load; });
    if (!body_force && !has_load && !physics_model->has_cell_load())
      {
        f = 0.;
        return;
      }
    const auto                          &fe = fe_collection[0];
    FEValues<dim>                        fe_values(fe,
                            QGauss<dim>(degree + 1),
                            update_values | update_gradients | update_quadrature_points |
                              update_JxW_values);
    FEFaceValues<dim>                    fe_face_values(fe,
                                     QGauss<dim - 1>(degree + 1),
                                     update_values | update_quadrature_points | update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    dealii::Vector<double>               cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    // Without a volume load only the cells with a loaded boundary face contribute (explicit runs
    // assemble the load every step).
    const bool volume_load = body_force || physics_model->has_cell_load();
    const auto loaded      = [this](const auto &cell) {
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          for (const auto &c : condition_list)
            if (c.type == Quantity::load && c.boundary_ids.count(cell->face(f)->boundary_id()) > 0)
              return true;
      return false;
    };
    f = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0 &&
          (volume_load || (cell->at_boundary() && loaded(cell))))
        {
          fe_values.reinit(cell);
          assemble_cell_load(cell, time, fe_values, fe_face_values, cell_rhs);
          cell->get_dof_indices(dofs);
          hanging_constraints.distribute_local_to_global(cell_rhs, dofs, f);
        }
    f.compress(VectorOperation::add);
  }

  template <int dim>
  double
  FERegion<dim>::stable_time_step(const FEVector *mass_in) const
  {
    const SetupTimes::Scope time(SetupStage::stable_time_step);
    const FEVector         &m = mass_in ? *mass_in : mass;
    // Gershgorin: lambda_max(M^-1 K) <= max_i sum_j |K_ij| / m_i.
    const auto sums  = absolute_row_sums();
    double     bound = 0.;
    for (unsigned int k = 0; k < sums.size(); ++k)
      if (m.local_element(k) > 0.)
        bound = std::max(bound, sums[k] / m.local_element(k));
    bound = Utilities::MPI::max(bound, comm);
    if (bound == 0.)
      return std::numeric_limits<double>::max();
    // Forward Euler of a first-order field is stable for dt lambda_max <= 2, velocity Verlet
    // for dt sqrt(lambda_max) <= 2.
    return layout.has_temperature() ? 2. / bound : 2. / std::sqrt(bound);
  }

  template <int dim>
  std::vector<double>
  FERegion<dim>::absolute_row_sums(const FEVector *x) const
  {
    // Rows read through Epetra views: deal.II's row iterator copies every row.
    const auto         &matrix = stiffness.trilinos_matrix();
    std::vector<double> sums(owned_dofs.n_elements(), 0.);
    for (int row = 0; row < matrix.NumMyRows(); ++row)
      {
        int     n_entries = 0;
        double *values    = nullptr;
        int    *columns   = nullptr;
        matrix.ExtractMyRowView(row, n_entries, values, columns);
        double sum = 0.;
        for (int k = 0; k < n_entries; ++k)
          sum += std::abs(values[k] * (x ? (*x)(matrix.ColMap().GID(columns[k])) : 1.));
        sums[owned_dofs.index_within_set(matrix.RowMap().GID(row))] = sum;
      }
    return sums;
  }

  template <int dim>
  double
  FERegion<dim>::strain_energy(const FEVector &u) const
  {
    FEVector Ku;
    initialize_vector(Ku);
    stiffness.vmult(Ku, u);
    return 0.5 * (Ku * u);
  }

  // The members defined in this file (the class is instantiated in fe_region.cc).
#define PERIDEAL_INSTANTIATE(dim)                                                            \
  template void                FERegion<dim>::assemble_matrices();                           \
  template void                FERegion<dim>::assemble_load(const double, FEVector &) const; \
  template double              FERegion<dim>::stable_time_step(const FEVector *) const;      \
  template std::vector<double> FERegion<dim>::absolute_row_sums(const FEVector *) const;     \
  template double              FERegion<dim>::strain_energy(const FEVector &) const;
  PERIDEAL_INSTANTIATE(2)
  PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
} // namespace perideal
