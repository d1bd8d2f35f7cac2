// ---------------------------------------------------------------------
// PeriDeal: small helpers to read parameter files.
// ---------------------------------------------------------------------
#ifndef perideal_base_parameter_utilities_h
#define perideal_base_parameter_utilities_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace perideal
{
  namespace ParameterUtilities
  {
    /**
     * @brief A small closed choice (STYLE.md, habit 7): its names with their enum values, in
     * the order of its Patterns::Selection. One table gives the pattern (selection()), the value
     * of a name (choice()) and the name of a value (choice_name()).
     */
    template <typename Enum>
    using Choices = std::vector<std::pair<std::string, Enum>>;

    /**
     * @brief The Patterns::Selection of @p choices: their names joined by '|'.
     */
    template <typename Enum>
    std::string
    selection(const Choices<Enum> &choices)
    {
      std::string names;
      for (const auto &[name, value] : choices)
        names += (names.empty() ? "" : "|") + name;
      return names;
    }

    /**
     * @brief The value named @p name in @p choices; throws, naming @p entry and the accepted
     * names, for another name.
     */
    template <typename Enum>
    Enum
    choice(const Choices<Enum> &choices, const std::string &name, const std::string &entry)
    {
      const auto  found = std::find_if(choices.begin(), choices.end(), [&](const auto &c) {
        return c.first == name;
      });
      std::string accepted;
      for (const auto &c : choices)
        accepted += (accepted.empty() ? "" : ", ") + c.first;
      AssertThrow(found != choices.end(),
                  dealii::ExcMessage("The parameter <" + entry + "> is <" + name +
                                     ">; accepted: " + accepted + "."));
      return found->second;
    }

    /**
     * @brief The name of @p value in @p choices.
     */
    template <typename Enum>
    const std::string &
    choice_name(const Choices<Enum> &choices, const Enum value)
    {
      const auto found = std::find_if(choices.begin(), choices.end(), [&](const auto &c) {
        return c.second == value;
      });
      Assert(found != choices.end(), dealii::ExcInternalError());
      return found->first;
    }

    /**
     * @brief Parse a comma-separated list of @p dim numbers into a point; the error names
     * @p entry.
     */
    template <int dim>
    dealii::Point<dim>
    parse_point(const std::string &text, const std::string &entry);

    /**
     * @brief Split a comma-separated list of names, trimming white space; empty items dropped.
     */
    std::vector<std::string>
    split_names(const std::string &text);

    /**
     * @brief Declare the entry "Names" (a comma-separated list) of subsection @p section; the
     * first pass over a file reads it to learn which named subsections to declare.
     */
    void
    declare_name_list(dealii::ParameterHandler &prm,
                      const std::string        &section,
                      const std::string        &documentation);

    /**
     * @brief The names listed in the entry "Names" of subsection @p section.
     */
    std::vector<std::string>
    parse_name_list(dealii::ParameterHandler &prm, const std::string &section);

    /**
     * @brief @p value with six significant digits, for messages.
     */
    std::string
    format_number(const double value);

    /**
     * @brief Throw, naming @p entry, unless @p value > 0.
     */
    void
    require_positive(const double value, const std::string &entry);

    /**
     * @brief Read only the entries declared in @p prm from @p filename, ignoring all others
     * (otherwise as parse_file()).
     *
     * Used for the first pass over a parameter file: the dimension and the lists of names that
     * decide which subsections exist are read before the full declaration.
     */
    void
    parse_partially(dealii::ParameterHandler &prm, const std::string &filename);

    /**
     * @brief Parse @p filename into @p prm (fully declared) with deal.II's parser, after two
     * steps of ours: an <tt>include</tt> and the value of an entry whose name ends in "file"
     * (<Finite elements/Mesh file>, a region's <Mesh file>, <Grains file>) that are relative
     * paths are taken relative to the folder of the file that names them if they exist there,
     * else relative to the working directory (as a script that copies a file elsewhere
     * expects). Errors name the file, its line and the entry with its section, e.g. "The
     * parameter <Material/antiplane state based/Stabilization> = <x> (line 12 of a.prm) does
     * not match its pattern ...", also where deal.II's pattern check refuses a value.
     */
    void
    parse_file(dealii::ParameterHandler &prm, const std::string &filename);

    /**
     * @brief A FunctionParser of @p n components from @p expression (one expression of x, y,
     * (z) and t per component, separated by ';', the constant pi defined; a single "0" is zero
     * for every component); throws, naming
     * @p entry, if the number of expressions differs from @p n or one does not parse.
     */
    template <int dim>
    std::unique_ptr<dealii::FunctionParser<dim>>
    make_function(const std::string &expression, const unsigned int n, const std::string &entry);

    /**
     * @brief Declare the entries "Components" (x, y, (z); default all) and "Function" (one
     * expression per listed component, or per component for a traction) of a boundary
     * condition, for particles and finite elements alike; read them with
     * parse_components() and make_function().
     */
    template <int dim>
    void
    declare_prescribed_components(dealii::ParameterHandler &prm);

    /**
     * @brief The time step of an explicit run: @p requested if it is positive (refused, naming
     * <Time stepping/Time step>, if above @p stable_dt, "the stable limit ... s of"
     * @p limited_by), else @p safety_factor times @p stable_dt.
     */
    double
    choose_time_step(const double       requested,
                     const double       safety_factor,
                     const double       stable_dt,
                     const std::string &limited_by = "this discretization");

    /**
     * @brief The number of equal steps, none longer than @p dt, that reach @p end_time (at least
     * one); @p dt becomes end_time / steps. Every explicit run (PD, FE, coupled) steps this way.
     */
    unsigned int
    equal_time_steps(const double end_time, double &dt);

    /**
     * @brief The component indices listed in the entry "Components".
     */
    std::vector<unsigned int>
    parse_components(dealii::ParameterHandler &prm);
  } // namespace ParameterUtilities
} // namespace perideal

#endif
