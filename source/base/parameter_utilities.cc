// ---------------------------------------------------------------------
// PeriDeal: small helpers to read parameter files.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/parameter_utilities.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace perideal
{
  namespace ParameterUtilities
  {
    template <int dim>
    dealii::Point<dim>
    parse_point(const std::string &text, const std::string &entry)
    {
      const std::vector<std::string> items = dealii::Utilities::split_string_list(text, ',');
      AssertThrow(items.size() == dim,
                  dealii::ExcMessage("The parameter <" + entry + "> = <" + text + "> must hold " +
                                     std::to_string(dim) +
                                     " comma-separated numbers (one per coordinate)."));
      dealii::Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        {
          try
            {
              p[d] = dealii::Utilities::string_to_double(items[d]);
            }
          catch (...)
            {
              AssertThrow(false,
                          dealii::ExcMessage("The parameter <" + entry + "> = <" + text +
                                             "> holds <" + items[d] + ">, which is not a number."));
            }
        }
      return p;
    }

    std::vector<std::string>
    split_names(const std::string &text)
    {
      std::vector<std::string> result;
      for (const std::string &item : dealii::Utilities::split_string_list(text, ','))
        if (!item.empty())
          result.push_back(item);
      return result;
    }

    void
    declare_name_list(dealii::ParameterHandler &prm,
                      const std::string        &section,
                      const std::string        &documentation)
    {
      prm.enter_subsection(section);
      prm.declare_entry("Names", "", dealii::Patterns::Anything(), documentation);
      prm.leave_subsection();
    }

    std::vector<std::string>
    parse_name_list(dealii::ParameterHandler &prm, const std::string &section)
    {
      prm.enter_subsection(section);
      const auto names = split_names(prm.get("Names"));
      prm.leave_subsection();
      return names;
    }

    std::string
    format_number(const double value)
    {
      std::ostringstream out;
      out << std::setprecision(6) << value;
      return out.str();
    }

    void
    require_positive(const double value, const std::string &entry)
    {
      AssertThrow(value > 0.,
                  dealii::ExcMessage("The parameter <" + entry + "> is " + format_number(value) +
                                     ", but it must be a number greater than zero."));
    }

    void
    parse_partially(dealii::ParameterHandler &prm, const std::string &filename)
    {
      AssertThrow(std::filesystem::exists(filename),
                  dealii::ExcMessage("The parameter file <" + filename + "> does not exist."));
      prm.parse_input(filename, "", /*skip_undefined=*/true);
    }

    void
    parse_file(dealii::ParameterHandler &prm, const std::string &filename)
    {
      AssertThrow(std::filesystem::exists(filename),
                  dealii::ExcMessage("The parameter file <" + filename + "> does not exist."));
      prm.parse_input(filename, "", /*skip_undefined=*/false, /*assert_mandatory=*/true);
    }

    template <int dim>
    std::unique_ptr<dealii::FunctionParser<dim>>
    make_function(const std::string &expression, const unsigned int n, const std::string &entry)
    {
      const std::string variables = dim == 2 ? "x,y,t" : "x,y,z,t";
      // A single "0" is zero for every component.
      std::string text = expression;
      if (dealii::Utilities::trim(expression) == "0")
        for (unsigned int k = 1; k < n; ++k)
          text += "; 0";
      const auto parts = dealii::Utilities::split_string_list(text, ';');
      AssertThrow(parts.size() == n,
                  dealii::ExcMessage("The parameter <" + entry + "> = <" + expression +
                                     "> must hold " + std::to_string(n) +
                                     " expression(s) separated by ';', one per component."));
      auto function = std::make_unique<dealii::FunctionParser<dim>>(n);
      try
        {
          function->initialize(variables,
                               text,
                               {{"pi", dealii::numbers::PI}},
                               /*time_dependent=*/true);
          // muparser compiles an expression at its first evaluation: evaluate every component
          // once, so that a malformed one is found here, when the file is read (deal.II prints
          // muparser's diagnosis to std::cerr first; the message below replaces it).
          std::ostringstream muparser_diagnosis;
          std::streambuf    *cerr_buffer = std::cerr.rdbuf(muparser_diagnosis.rdbuf());
          try
            {
              for (unsigned int c = 0; c < n; ++c)
                function->value(dealii::Point<dim>(), c);
            }
          catch (...)
            {
              std::cerr.rdbuf(cerr_buffer);
              throw;
            }
          std::cerr.rdbuf(cerr_buffer);
        }
      catch (...)
        {
          AssertThrow(false,
                      dealii::ExcMessage("The parameter <" + entry + "> = <" + expression +
                                         "> is not a valid expression of " + variables +
                                         " (and the constant pi)."));
        }
      return function;
    }

    template <int dim>
    void
    declare_prescribed_components(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Components",
                        dim == 2 ? "x, y" : "x, y, z",
                        dealii::Patterns::MultipleSelection(dim == 2 ? "x|y" : "x|y|z"),
                        "The prescribed components (displacement, velocity); ignored for "
                        "traction.");
      prm.declare_entry("Function",
                        "0",
                        dealii::Patterns::Anything(),
                        "One expression of x, y, (z) and t [s] per listed component (all dim "
                        "components for traction), separated by ';'; a single 0 is zero for "
                        "all.");
    }

    double
    choose_time_step(const double requested, const double safety_factor, const double stable_dt)
    {
      if (requested <= 0.)
        return safety_factor * stable_dt;
      AssertThrow(requested <= stable_dt,
                  dealii::ExcMessage(
                    "The parameter <Time stepping/Time step> = " + format_number(requested) +
                    " s exceeds the stable limit " + format_number(stable_dt) +
                    " s of this discretization; accepted: 0 (automatic) or a "
                    "value up to the limit."));
      return requested;
    }

    unsigned int
    equal_time_steps(const double end_time, double &dt)
    {
      const unsigned int n_steps =
        std::max<unsigned int>(1, static_cast<unsigned int>(std::ceil(end_time / dt - 1e-6)));
      dt = end_time / n_steps;
      return n_steps;
    }

    std::vector<unsigned int>
    parse_components(dealii::ParameterHandler &prm)
    {
      std::vector<unsigned int> components;
      for (const auto &name : dealii::Utilities::split_string_list(prm.get("Components"), ','))
        components.push_back(name == "x" ? 0 : name == "y" ? 1 : 2);
      return components;
    }

    template dealii::Point<2>
    parse_point<2>(const std::string &, const std::string &);
    template dealii::Point<3>
    parse_point<3>(const std::string &, const std::string &);
    template void
    declare_prescribed_components<2>(dealii::ParameterHandler &);
    template void
    declare_prescribed_components<3>(dealii::ParameterHandler &);
    template std::unique_ptr<dealii::FunctionParser<2>>
    make_function<2>(const std::string &, const unsigned int, const std::string &);
    template std::unique_ptr<dealii::FunctionParser<3>>
    make_function<3>(const std::string &, const unsigned int, const std::string &);
  } // namespace ParameterUtilities
} // namespace perideal
