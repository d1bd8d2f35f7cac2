// ---------------------------------------------------------------------
// PeriDeal: FE physics 'heat'.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <perideal/base/elasticity.h>
#include <perideal/base/parameter_utilities.h>
#include <perideal/fem/physics/heat_conduction.h>

#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    const std::string section = "Finite elements/heat";

    template <int dim>
    const ParameterUtilities::Choices<typename HeatConduction<dim>::Symmetry> &
    symmetries()
    {
      using Symmetry = typename HeatConduction<dim>::Symmetry;
      static const ParameterUtilities::Choices<Symmetry> names =
        {{"isotropic", Symmetry::isotropic}, {"orthotropic", Symmetry::orthotropic}};
      return names;
    }

    // The heat flux -K grad T.
    template <int dim>
    class HeatFluxPostprocessor : public DataPostprocessor<dim>
    {
    public:
      explicit HeatFluxPostprocessor(const Tensor<2, dim> &K)
        : K(K)
      {}

      std::vector<std::string>
      get_names() const override
      {
        std::vector<std::string> names;
        for (unsigned int d = 0; d < dim; ++d)
          names.push_back(std::string("heat_flux_") + "xyz"[d]);
        return names;
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        return std::vector<DataComponentInterpretation::DataComponentInterpretation>(
          dim,
          DataComponentInterpretation::component_is_scalar);
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients;
      }

      void
      evaluate_scalar_field(const DataPostprocessorInputs::Scalar<dim> &inputs,
                            std::vector<dealii::Vector<double>>        &computed) const override
      {
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            const Tensor<1, dim> flux = -(K * inputs.solution_gradients[q]);
            for (unsigned int d = 0; d < dim; ++d)
              computed[q][d] = flux[d];
          }
      }

    private:
      const Tensor<2, dim> K;
    };
  } // namespace

  template <int dim>
  void
  HeatConduction<dim>::declare_parameters(ParameterHandler &prm) const
  {
    prm.enter_subsection("heat");
    prm.declare_entry("Symmetry",
                      "isotropic",
                      Patterns::Selection(ParameterUtilities::selection(symmetries<dim>())),
                      "Symmetry class of the conductivity: isotropic (<Conductivity>) or "
                      "orthotropic (<Conductivities> along the material axes 1, 2, 3, oriented "
                      "by <Orientation>).");
    prm.declare_entry("Conductivity",
                      "1",
                      Patterns::Double(),
                      "isotropic: the thermal conductivity k > 0 [W/(m K)] of Fourier's law "
                      "q = -k grad T.");
    prm.declare_entry("Conductivities",
                      "1, 1, 1",
                      Patterns::List(Patterns::Double(), 3, 3),
                      "orthotropic: k1, k2, k3 > 0 [W/(m K)] along the material axes (a 2D "
                      "problem uses the in-plane block of the rotated tensor).");
    prm.declare_entry("Orientation",
                      "0, 0, 0",
                      Patterns::List(Patterns::Double(), 3, 3),
                      "orthotropic: z-x-z Euler angles phi, theta, psi [degrees] of the material "
                      "axes with respect to the global axes (the convention of <Finite "
                      "elements/Elasticity/Orientation>). In 2D only phi keeps the plane a "
                      "symmetry plane.");
    prm.declare_entry("Specific heat",
                      "1",
                      Patterns::Double(),
                      "The specific heat capacity c > 0 [J/(kg K)]: with <Finite "
                      "elements/Density> rho the heat capacity rho c [J/(m^3 K)] of the "
                      "transient solves.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  HeatConduction<dim>::parse_parameters(ParameterHandler &prm, const PlanarAssumption)
  {
    prm.enter_subsection("heat");
    symmetry =
      ParameterUtilities::choice(symmetries<dim>(), prm.get("Symmetry"), section + "/Symmetry");
    const auto numbers = [&](const std::string &entry) {
      std::array<double, 3> values{};
      const auto            items = Utilities::split_string_list(prm.get(entry), ',');
      for (unsigned int d = 0; d < 3; ++d)
        values[d] = Utilities::string_to_double(items[d]);
      return values;
    };
    if (symmetry == Symmetry::isotropic)
      {
        const double k = prm.get_double("Conductivity");
        ParameterUtilities::require_positive(k, section + "/Conductivity");
        principal   = {{k, k, k}};
        orientation = {{0., 0., 0.}};
      }
    else
      {
        principal = numbers("Conductivities");
        for (const double k : principal)
          AssertThrow(k > 0.,
                      ExcMessage("The parameter <" + section + "/Conductivities> holds " +
                                 ParameterUtilities::format_number(k) +
                                 "; accepted values are k1, k2, k3 > 0."));
        orientation = numbers("Orientation");
      }
    specific_heat = prm.get_double("Specific heat");
    ParameterUtilities::require_positive(specific_heat, section + "/Specific heat");
    prm.leave_subsection();

    // K = R diag(k1, k2, k3) R^T (the columns of R are the material axes); its in-plane block
    // in 2D.
    const Tensor<2, 3> R =
      rotation_from_euler_angles(orientation[0], orientation[1], orientation[2]);
    K = Tensor<2, dim>();
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int a = 0; a < 3; ++a)
          K[i][j] += R[i][a] * principal[a] * R[j][a];
  }

  template <int dim>
  FieldLayout
  HeatConduction<dim>::field_layout() const
  {
    return FieldLayout::temperature();
  }

  template <int dim>
  void
  HeatConduction<dim>::add_cell_stiffness(const FEValues<dim> &fe_values,
                                          const types::material_id,
                                          const std::vector<double> &weights,
                                          FullMatrix<double>        &cell_matrix) const
  {
    const unsigned int n = fe_values.dofs_per_cell;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      for (unsigned int i = 0; i < n; ++i)
        {
          const Tensor<1, dim> K_grad = weights[q] * (K * fe_values.shape_grad(i, q));
          for (unsigned int j = i; j < n; ++j)
            cell_matrix(i, j) += K_grad * fe_values.shape_grad(j, q);
        }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < i; ++j)
        cell_matrix(i, j) = cell_matrix(j, i);
  }

  template <int dim>
  double
  HeatConduction<dim>::mass_factor() const
  {
    return specific_heat;
  }

  template <int dim>
  std::unique_ptr<DataPostprocessor<dim>>
  HeatConduction<dim>::postprocessor() const
  {
    return std::make_unique<HeatFluxPostprocessor<dim>>(K);
  }

  template <int dim>
  std::string
  HeatConduction<dim>::summary() const
  {
    std::ostringstream out;
    out << "heat conduction, ";
    if (symmetry == Symmetry::isotropic)
      out << "k = " << principal[0];
    else
      out << "orthotropic k1, k2, k3 = " << principal[0] << ", " << principal[1] << ", "
          << principal[2] << " W/(m K), orientation " << orientation[0] << ", " << orientation[1]
          << ", " << orientation[2] << " degrees";
    out << (symmetry == Symmetry::isotropic ? " W/(m K)" : "") << ", c = " << specific_heat
        << " J/(kg K)";
    return out.str();
  }

  template <int dim>
  const Tensor<2, dim> &
  HeatConduction<dim>::conductivity() const
  {
    return K;
  }

  template class HeatConduction<2>;
  template class HeatConduction<3>;
} // namespace perideal

PERIDEAL_REGISTER_FE_PHYSICS(perideal::HeatConduction,
                             "heat",
                             "transient heat conduction rho c dT/dt - div(K grad T) = q, unknown "
                             "the temperature T, K isotropic or orthotropic in material axes; "
                             "parameters in <Finite elements/heat>.")
