// ---------------------------------------------------------------------
// PeriDeal: FE physics 'scalar laplace'.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/fem/physics/scalar_laplace.h>

#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    const std::string section = "Finite elements/scalar laplace";

    // The gradient of w and the flux k grad w (tau_xz, tau_yz of antiplane shear).
    template <int dim>
    class FluxPostprocessor : public DataPostprocessor<dim>
    {
    public:
      explicit FluxPostprocessor(const ScalarLaplace<dim> &physics)
        : physics(physics)
      {}

      std::vector<std::string>
      get_names() const override
      {
        std::vector<std::string> names;
        for (const std::string quantity : {"dw_d", "flux_"})
          for (unsigned int d = 0; d < dim; ++d)
            names.push_back(quantity + "xyz"[d]);
        return names;
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        return std::vector<DataComponentInterpretation::DataComponentInterpretation>(
          2 * dim,
          DataComponentInterpretation::component_is_scalar);
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients | update_quadrature_points;
      }

      void
      evaluate_scalar_field(const DataPostprocessorInputs::Scalar<dim> &inputs,
                            std::vector<dealii::Vector<double>>        &computed) const override
      {
        const double k = physics.coefficient(inputs.template get_cell<dim>()->material_id());
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            const Tensor<1, dim> gamma =
              inputs.solution_gradients[q] +
              (physics.torsion().active() ?
                 physics.torsion().twist_strain(inputs.evaluation_points[q]) :
                 Tensor<1, dim>());
            for (unsigned int d = 0; d < dim; ++d)
              {
                computed[q][d]       = inputs.solution_gradients[q][d];
                computed[q][dim + d] = k * gamma[d];
              }
          }
      }

    private:
      const ScalarLaplace<dim> &physics;
    };
  } // namespace

  template <int dim>
  void
  ScalarLaplace<dim>::declare_parameters(ParameterHandler &prm) const
  {
    prm.enter_subsection("scalar laplace");
    prm.declare_entry("Coefficient",
                      "1",
                      Patterns::Double(),
                      "The coefficient k > 0 of -div(k grad w) = f, in units of the source f "
                      "times m^2 per unit of w (antiplane shear: the shear modulus mu [Pa], w "
                      "[m], f [N/m^3]; heat conduction: the conductivity [W/(m K)]).");
    prm.declare_entry("Coefficients by material id",
                      "",
                      Patterns::Anything(),
                      "k of the cells with a given material id (gmsh physical surface/volume "
                      "or generator), as 'id: k' items separated by ',' (e.g. '1: 8e10, 2: "
                      "4e10'); other cells take <Coefficient>.");
    Torsion::declare_parameters(prm);
    prm.leave_subsection();
  }

  template <int dim>
  void
  ScalarLaplace<dim>::parse_parameters(ParameterHandler &prm, const PlanarAssumption)
  {
    prm.enter_subsection("scalar laplace");
    default_coefficient = prm.get_double("Coefficient");
    AssertThrow(default_coefficient > 0.,
                ExcMessage("The parameter <" + section + "/Coefficient> is " +
                           ParameterUtilities::format_number(default_coefficient) +
                           "; accepted values are > 0."));
    coefficients.clear();
    const std::string entry = "<" + section + "/Coefficients by material id>";
    for (const auto &item :
         Utilities::split_string_list(prm.get("Coefficients by material id"), ','))
      {
        const auto parts = Utilities::split_string_list(item, ':');
        AssertThrow(parts.size() == 2,
                    ExcMessage("The parameter " + entry + " item <" + item +
                               "> is not of the form 'id: k'."));
        int    id = -1;
        double k  = 0.;
        try
          {
            id = Utilities::string_to_int(parts[0]);
            k  = Utilities::string_to_double(parts[1]);
          }
        catch (const std::exception &)
          {
            AssertThrow(false,
                        ExcMessage("The parameter " + entry + " item <" + item +
                                   "> is not of the form 'id: k' with an integer id and a "
                                   "number k."));
          }
        AssertThrow(id >= 0 && k > 0.,
                    ExcMessage("The parameter " + entry + " item <" + item +
                               ">: accepted are material ids >= 0 and k > 0."));
        coefficients[static_cast<types::material_id>(id)] = k;
      }
    twist.parse_parameters(prm, section, dim);
    prm.leave_subsection();
  }

  template <int dim>
  FieldLayout
  ScalarLaplace<dim>::field_layout() const
  {
    return FieldLayout::scalar("w");
  }

  template <int dim>
  double
  ScalarLaplace<dim>::coefficient(const types::material_id material_id) const
  {
    const auto found = coefficients.find(material_id);
    return found == coefficients.end() ? default_coefficient : found->second;
  }

  template <int dim>
  const Torsion &
  ScalarLaplace<dim>::torsion() const
  {
    return twist;
  }

  template <int dim>
  void
  ScalarLaplace<dim>::add_cell_stiffness(const FEValues<dim>       &fe_values,
                                         const types::material_id   material_id,
                                         const std::vector<double> &weights,
                                         FullMatrix<double>        &cell_matrix) const
  {
    const unsigned int n = fe_values.dofs_per_cell;
    const double       k = coefficient(material_id);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const double w = k * weights[q];
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = i; j < n; ++j)
            cell_matrix(i, j) += (fe_values.shape_grad(i, q) * fe_values.shape_grad(j, q)) * w;
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < i; ++j)
        cell_matrix(i, j) = cell_matrix(j, i);
  }

  template <int dim>
  bool
  ScalarLaplace<dim>::has_cell_load() const
  {
    return twist.active();
  }

  template <int dim>
  void
  ScalarLaplace<dim>::add_cell_load(const FEValues<dim>       &fe_values,
                                    const types::material_id   material_id,
                                    const std::vector<double> &weights,
                                    dealii::Vector<double>    &cell_rhs) const
  {
    if (!twist.active())
      return;
    // The energy k/2 |grad w + gamma_t|^2 has the load -k grad phi_i . gamma_t: with weight 1
    // and one k it integrates by parts to the traction-free data -k gamma_t . n on the
    // boundary (div gamma_t = 0); with the weight 1 - beta of a blended problem it is the load
    // of the weighted energy, which the boundary form is not.
    const double k = coefficient(material_id);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const Tensor<1, dim> load =
          -k * weights[q] * twist.twist_strain(fe_values.quadrature_point(q));
        for (unsigned int i = 0; i < fe_values.dofs_per_cell; ++i)
          cell_rhs(i) += load * fe_values.shape_grad(i, q);
      }
  }

  template <int dim>
  std::optional<std::pair<Point<dim>, std::string>>
  ScalarLaplace<dim>::held_point() const
  {
    if (!twist.active())
      return {};
    Point<dim> p;
    p[0] = twist.axis()[0];
    p[1] = twist.axis()[1];
    return std::make_pair(p, twist.axis_entry());
  }

  template <int dim>
  std::vector<std::string>
  ScalarLaplace<dim>::integral_names() const
  {
    if (!twist.active())
      return {};
    return {"torque", "torsion_energy"};
  }

  template <int dim>
  void
  ScalarLaplace<dim>::add_cell_integrals(const FEValues<dim>          &fe_values,
                                         const types::material_id      material_id,
                                         const std::vector<double>    &weights,
                                         const dealii::Vector<double> &cell_values,
                                         std::vector<double>          &integrals) const
  {
    if (!twist.active())
      return;
    const double k = coefficient(material_id);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const Point<dim> &x     = fe_values.quadrature_point(q);
        Tensor<1, dim>    gamma = twist.twist_strain(x);
        for (unsigned int i = 0; i < fe_values.dofs_per_cell; ++i)
          gamma += cell_values(i) * fe_values.shape_grad(i, q);
        const Tensor<1, dim> tau = k * gamma;
        integrals[0] += twist.torque_density(x, tau) * weights[q];
        integrals[1] += 0.5 * (tau * gamma) * weights[q];
      }
  }

  template <int dim>
  std::unique_ptr<DataPostprocessor<dim>>
  ScalarLaplace<dim>::postprocessor() const
  {
    return std::make_unique<FluxPostprocessor<dim>>(*this);
  }

  template <int dim>
  std::string
  ScalarLaplace<dim>::summary() const
  {
    std::ostringstream out;
    out << "scalar laplace, k = " << default_coefficient;
    for (const auto &[id, k] : coefficients)
      out << ", k(" << static_cast<unsigned int>(id) << ") = " << k;
    if (twist.active())
      out << ", torsion: twist " << twist.twist() << " rad/m about (" << twist.axis() << ")";
    return out.str();
  }

  template class ScalarLaplace<2>;
  template class ScalarLaplace<3>;
} // namespace perideal

PERIDEAL_REGISTER_FE_PHYSICS(perideal::ScalarLaplace,
                             "scalar laplace",
                             "a scalar field w with -div(k grad w) = f (antiplane shear with k = "
                             "mu, diffusion), k per material id; parameters in <Finite "
                             "elements/scalar laplace>.")
