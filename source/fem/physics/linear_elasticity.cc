// ---------------------------------------------------------------------
// PeriDeal: FE physics 'linear elasticity'.
// ---------------------------------------------------------------------
#include <perideal/fem/physics/linear_elasticity.h>

#include <cmath>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // Strain, stress and von Mises stress from the displacement gradient; with a temperature
    // change, the stress of the mechanical strain, the temperature change, the mechanical
    // strain and the free thermal strain in the plane.
    template <int dim>
    class StressPostprocessor : public DataPostprocessor<dim>
    {
    public:
      // The thermal members are only read with a non-empty delta_T.
      StressPostprocessor(const SymmetricTensor<4, dim>     &C,
                          const FullMatrix<double>          &voigt,
                          const PlanarAssumption             planar,
                          const SymmetricTensor<2, dim>     &alpha,
                          const SymmetricTensor<2, dim>     &free_expansion,
                          const SymmetricTensor<2, dim>     &thermal_stress,
                          const double                       thermal_stress_zz,
                          const PointTemperatureChange<dim> &delta_T)
        : C(C)
        , voigt(voigt)
        , planar(planar)
        , alpha(alpha)
        , free_expansion(free_expansion)
        , thermal_stress(thermal_stress)
        , thermal_stress_zz(thermal_stress_zz)
        , delta_T(delta_T)
      {}

      std::vector<std::string>
      get_names() const override
      {
        std::vector<std::string> names;
        const char               axes[] = {'x', 'y', 'z'};
        for (const std::string quantity : {"strain", "stress"})
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              names.push_back(quantity + "_" + axes[i] + axes[j]);
        if (dim == 2)
          names.push_back("stress_zz");
        names.push_back("von_mises_stress");
        if (delta_T)
          {
            names.push_back("temperature_change");
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                names.push_back(std::string("mechanical_strain_") + axes[i] + axes[j]);
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                names.push_back(std::string("thermal_strain_") + axes[i] + axes[j]);
          }
        return names;
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        return std::vector<DataComponentInterpretation::DataComponentInterpretation>(
          get_names().size(),
          DataComponentInterpretation::component_is_scalar);
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return delta_T ? update_gradients | update_quadrature_points : update_gradients;
      }

      void
      evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                            std::vector<dealii::Vector<double>>        &computed) const override
      {
        std::vector<double> dT(inputs.solution_gradients.size(), 0.);
        if (delta_T)
          delta_T(inputs.template get_cell<dim>(), inputs.evaluation_points, dT);
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            Tensor<2, dim> grad;
            for (unsigned int c = 0; c < dim; ++c)
              grad[c] = inputs.solution_gradients[q][c];
            const SymmetricTensor<2, dim> eps   = symmetrize(grad);
            const SymmetricTensor<2, dim> sigma = C * eps - dT[q] * thermal_stress;
            unsigned int                  k     = 0;
            for (const auto *t : {&eps, &sigma})
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = i; j < dim; ++j)
                  computed[q][k++] = (*t)[i][j];
            // The out-of-plane stress: 0 in plane stress, C_33kl eps_kl - (C alpha)_33 Delta T
            // in plane strain.
            double s33 = 0.;
            if (dim == 2 && planar == PlanarAssumption::plane_strain)
              s33 = voigt(2, 0) * eps[0][0] + voigt(2, 1) * eps[1][1] +
                    voigt(2, 5) * 2. * eps[0][dim - 1] - thermal_stress_zz * dT[q];
            if (dim == 2)
              computed[q][k++] = s33;
            SymmetricTensor<2, 3> s3;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                s3[i][j] = sigma[i][j];
            if (dim == 2)
              s3[2][2] = s33;
            const SymmetricTensor<2, 3> dev = deviator(s3);
            computed[q][k++]                = std::sqrt(1.5 * (dev * dev));
            if (delta_T)
              {
                computed[q][k++]                         = dT[q];
                const SymmetricTensor<2, dim> mechanical = eps - dT[q] * alpha;
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int j = i; j < dim; ++j)
                    computed[q][k++] = mechanical[i][j];
                // The free strain of the temperature change in the plane (alpha_2D Delta T).
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int j = i; j < dim; ++j)
                    computed[q][k++] = dT[q] * free_expansion[i][j];
              }
          }
      }

    private:
      const SymmetricTensor<4, dim>     C;
      const FullMatrix<double>          voigt;
      const PlanarAssumption            planar;
      const SymmetricTensor<2, dim>     alpha;
      const SymmetricTensor<2, dim>     free_expansion;
      const SymmetricTensor<2, dim>     thermal_stress;
      const double                      thermal_stress_zz;
      const PointTemperatureChange<dim> delta_T;
    };
  } // namespace

  template <int dim>
  void
  LinearElasticity<dim>::declare_parameters(ParameterHandler &prm) const
  {
    prm.enter_subsection("Elasticity");
    ElasticMaterial::declare_parameters(prm);
    prm.declare_entry("Same material as the particles",
                      "false",
                      Patterns::Bool(),
                      "true: take the symmetry class, constants, orientation and thermal "
                      "expansion from the particles' material subsection <Material/<Model>> (the "
                      "models with these entries: anisotropic bond based, anisotropic plane "
                      "stress), so that one block serves both regions; the other entries here "
                      "are then not read. "
                      "false: the entries of this subsection.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  LinearElasticity<dim>::parse_parameters(ParameterHandler &prm, const PlanarAssumption planar_)
  {
    planar = planar_;
    prm.enter_subsection("Elasticity");
    shared = prm.get_bool("Same material as the particles");
    if (!shared)
      material.parse_parameters(prm, "Finite elements/Elasticity");
    prm.leave_subsection();
    if (shared)
      {
        // The particles' subsection <Material/<Model>>, from the root (prm is in <Finite
        // elements>).
        prm.leave_subsection();
        const std::string model = prm.get({"Material"}, "Model");
        prm.enter_subsection("Material");
        prm.enter_subsection(model);
        // A model without the entries has no <Symmetry> (a declared one is never empty).
        AssertThrow(!prm.get("Symmetry").empty(),
                    ExcMessage("<Finite elements/Elasticity/Same material as the particles> = "
                               "true, but the particles' model <Material/Model> = " +
                               model +
                               " has no elastic constants of its own to share; accepted: a "
                               "model with the FE side's material entries (anisotropic bond "
                               "based, anisotropic plane stress), or false and the constants in "
                               "<Finite elements/Elasticity>."));
        material.parse_parameters(prm, "Material/" + model);
        prm.leave_subsection();
        prm.leave_subsection();
        prm.enter_subsection("Finite elements");
      }
    C = material.tensor<dim>(planar);
    // The thermal strain (doc/theory/thermal_strain_fe.md): the stress C : alpha_2D per kelvin
    // of the reduced expansion, and the energy 1/2 alpha : C : alpha per kelvin squared of the
    // 3D body (plane strain: with its out-of-plane part).
    const SymmetricTensor<2, 3> alpha_3d = material.thermal_expansion();
    const auto                  C_3d =
      reduce_elasticity_tensor<3>(material.voigt_stiffness(), PlanarAssumption::three_dimensional);
    planar_alpha      = planar_thermal_expansion<dim>(alpha_3d, material.voigt_stiffness(), planar);
    thermal_stress    = C * planar_alpha;
    thermal_stress_zz = (C_3d * alpha_3d)[2][2];
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        alpha[i][j] = alpha_3d[i][j];
    thermal_energy =
      planar == PlanarAssumption::plane_stress ? alpha * C * alpha : alpha_3d * C_3d * alpha_3d;
  }

  template <int dim>
  bool
  LinearElasticity<dim>::shares_particle_material() const
  {
    return shared;
  }

  template <int dim>
  FieldLayout
  LinearElasticity<dim>::field_layout() const
  {
    return FieldLayout::displacement(dim);
  }

  template <int dim>
  void
  LinearElasticity<dim>::add_cell_stiffness(const FEValues<dim> &fe_values,
                                            const types::material_id,
                                            const std::vector<double> &weights,
                                            FullMatrix<double>        &cell_matrix) const
  {
    const unsigned int                   n = fe_values.dofs_per_cell;
    const FEValuesExtractors::Vector     displacements(0);
    std::vector<SymmetricTensor<2, dim>> eps(n);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const double w = weights[q];
        if (w == 0.)
          continue;
        for (unsigned int i = 0; i < n; ++i)
          eps[i] = fe_values[displacements].symmetric_gradient(i, q);
        for (unsigned int i = 0; i < n; ++i)
          {
            const SymmetricTensor<2, dim> C_eps = C * eps[i];
            for (unsigned int j = i; j < n; ++j)
              cell_matrix(i, j) += (C_eps * eps[j]) * w;
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < i; ++j)
        cell_matrix(i, j) = cell_matrix(j, i);
  }

  template <int dim>
  bool
  LinearElasticity<dim>::has_thermal_strain() const
  {
    return !material.thermal_expansion_entry().is_zero();
  }

  template <int dim>
  void
  LinearElasticity<dim>::add_cell_thermal_load(const FEValues<dim> &fe_values,
                                               const types::material_id,
                                               const std::vector<double> &weights,
                                               const std::vector<double> &delta_T,
                                               dealii::Vector<double>    &cell_rhs) const
  {
    const FEValuesExtractors::Vector displacements(0);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const double w = weights[q] * delta_T[q];
        if (w == 0.)
          continue;
        for (unsigned int i = 0; i < fe_values.dofs_per_cell; ++i)
          cell_rhs(i) += (fe_values[displacements].symmetric_gradient(i, q) * thermal_stress) * w;
      }
  }

  template <int dim>
  double
  LinearElasticity<dim>::thermal_energy_density(const types::material_id,
                                                const double delta_T) const
  {
    return 0.5 * thermal_energy * delta_T * delta_T;
  }

  template <int dim>
  double
  LinearElasticity<dim>::thermoelastic_coupling_modulus() const
  {
    return thermal_stress * planar_alpha;
  }

  template <int dim>
  void
  LinearElasticity<dim>::cell_thermoelastic_measure(const FEValues<dim> &fe_values,
                                                    const types::material_id,
                                                    const dealii::Vector<double> &cell_values,
                                                    std::vector<double>          &measure) const
  {
    const FEValuesExtractors::Vector displacements(0);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        SymmetricTensor<2, dim> eps;
        for (unsigned int i = 0; i < fe_values.dofs_per_cell; ++i)
          eps += cell_values(i) * fe_values[displacements].symmetric_gradient(i, q);
        measure[q] = thermal_stress * eps;
      }
  }

  template <int dim>
  std::unique_ptr<DataPostprocessor<dim>>
  LinearElasticity<dim>::postprocessor() const
  {
    return thermal_postprocessor({});
  }

  template <int dim>
  std::unique_ptr<DataPostprocessor<dim>>
  LinearElasticity<dim>::thermal_postprocessor(const PointTemperatureChange<dim> &delta_T) const
  {
    return std::make_unique<StressPostprocessor<dim>>(C,
                                                      material.voigt_stiffness(),
                                                      planar,
                                                      alpha,
                                                      planar_alpha,
                                                      thermal_stress,
                                                      thermal_stress_zz,
                                                      delta_T);
  }

  template <int dim>
  std::string
  LinearElasticity<dim>::summary() const
  {
    return "material " + material.summary();
  }

  template <int dim>
  const SymmetricTensor<4, dim> &
  LinearElasticity<dim>::elasticity_tensor() const
  {
    return C;
  }

  template class LinearElasticity<2>;
  template class LinearElasticity<3>;
} // namespace perideal

PERIDEAL_REGISTER_FE_PHYSICS(perideal::LinearElasticity,
                             "linear elasticity",
                             "small-strain linear elasticity, -div(C : eps(u)) = b, unknowns the "
                             "displacement x, y(, z); material in <Finite elements/Elasticity>.")
