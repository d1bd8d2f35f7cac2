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

    namespace
    {
      // Where a line of the text handed to deal.II's parser comes from, and the subsection it
      // is in ("Material/antiplane state based").
      struct SourceLine
      {
        std::string  file;
        unsigned int line;
        std::string  section;
      };

      // A statement "KEYWORD rest" (lower or upper case, as deal.II accepts): rest, trimmed.
      bool
      match_keyword(const std::string &line, const std::string &keyword, std::string &rest)
      {
        std::string upper = keyword;
        std::transform(upper.begin(), upper.end(), upper.begin(), ::toupper);
        for (const std::string &word : {keyword, upper})
          if (line.compare(0, word.size() + 1, word + " ") == 0)
            {
              rest = dealii::Utilities::trim(line.substr(word.size() + 1));
              return true;
            }
        return false;
      }

      // @p name relative to the folder of @p file if it is a relative path that exists there;
      // else @p name as given (relative to the working directory).
      std::string
      resolve_path(const std::string &name, const std::string &file)
      {
        const std::filesystem::path path(name);
        if (name.empty() || path.is_absolute())
          return name;
        const std::filesystem::path beside = std::filesystem::path(file).parent_path() / path;
        return std::filesystem::exists(beside) ? beside.string() : name;
      }

      std::string
      joined(const std::vector<std::string> &sections)
      {
        std::string path;
        for (const auto &section : sections)
          path += (path.empty() ? "" : "/") + section;
        return path;
      }

      // Append the statements of @p filename to @p text, one per line (continuation lines
      // joined as deal.II joins them), its includes expanded in place and the relative paths
      // of its entries "... file" resolved by resolve_path(); @p origin gets each line's source
      // and @p sections is the subsection path at the end.
      void
      expand(const std::string        &filename,
             std::ostringstream       &text,
             std::vector<SourceLine>  &origin,
             std::vector<std::string> &sections,
             const unsigned int        depth)
      {
        AssertThrow(depth < 32,
                    dealii::ExcMessage("The parameter file <" + filename +
                                       "> is included from itself (an include cycle)."));
        std::ifstream input(filename);
        AssertThrow(input,
                    dealii::ExcMessage("The parameter file <" + filename + "> cannot be read."));
        std::string  physical, logical;
        unsigned int line_number = 0, first_line = 0;
        while (std::getline(input, physical))
          {
            ++line_number;
            physical = dealii::Utilities::trim(physical);
            if (logical.empty())
              first_line = line_number;
            if (!physical.empty() && physical.back() == '\\')
              {
                logical += physical.substr(0, physical.size() - 1);
                continue;
              }
            logical += physical;
            std::string statement = logical.substr(0, logical.find('#')), rest;
            std::replace(statement.begin(), statement.end(), '\t', ' ');
            statement = dealii::Utilities::trim(statement);
            if (match_keyword(statement, "include", rest))
              {
                const std::string included = resolve_path(rest, filename);
                AssertThrow(std::filesystem::exists(included),
                            dealii::ExcMessage("Line " + std::to_string(first_line) + " of file <" +
                                               filename + ">: the included file <" + rest +
                                               "> exists neither in the folder of this file nor "
                                               "in the working directory."));
                expand(included, text, origin, sections, depth + 1);
                logical.clear();
                continue;
              }
            if (match_keyword(statement, "subsection", rest))
              sections.push_back(rest);
            else if ((statement == "end" || statement == "END") && !sections.empty())
              sections.pop_back();
            else if (match_keyword(statement, "set", rest) && rest.find('=') != std::string::npos)
              {
                const std::string name  = dealii::Utilities::trim(rest.substr(0, rest.find('=')));
                const std::string value = dealii::Utilities::trim(rest.substr(rest.find('=') + 1));
                if (name.size() >= 4 && name.compare(name.size() - 4, 4, "file") == 0)
                  logical = "set " + name + " = " + resolve_path(value, filename);
              }
            text << logical << '\n';
            origin.push_back({filename, first_line, joined(sections)});
            logical.clear();
          }
      }

      // deal.II's parser on @p filename prepared by expand(); its errors are given back with
      // the file and line the statement comes from and the entry's section.
      void
      parse(dealii::ParameterHandler &prm, const std::string &filename, const bool skip_undefined)
      {
        AssertThrow(std::filesystem::exists(filename),
                    dealii::ExcMessage("The parameter file <" + filename + "> does not exist."));
        std::ostringstream       text;
        std::vector<SourceLine>  origin;
        std::vector<std::string> sections;
        expand(filename, text, origin, sections, 0);
        std::istringstream input(text.str());
        try
          {
            prm.parse_input(input, filename, "", skip_undefined);
            if (!skip_undefined)
              prm.assert_that_entries_have_been_set();
          }
        catch (const dealii::ExceptionBase &exc)
          {
            std::ostringstream info;
            exc.print_info(info);
            std::string message = info.str();
            // deal.II names the line of the prepared text: "Line <N> of file <F>".
            const std::string prefix = "Line <";
            const auto        start  = message.find(prefix);
            if (start == std::string::npos)
              throw;
            const unsigned int n         = std::stoul(message.substr(start + prefix.size()));
            const std::string  file_text = "of file <" + filename;
            auto               end       = message.find(file_text, start);
            if (n == 0 || n > origin.size() || end == std::string::npos)
              throw;
            end                      = message.find_first_not_of(">:", end + file_text.size());
            const SourceLine &source = origin[n - 1];
            const std::string where =
              "line " + std::to_string(source.line) + " of <" + source.file + ">";
            const std::string  pattern_text = "does not match the given pattern:";
            const auto         pattern      = message.find(pattern_text);
            std::istringstream statement(text.str());
            std::string        line;
            for (unsigned int k = 0; k < n; ++k)
              std::getline(statement, line);
            std::string rest;
            match_keyword(dealii::Utilities::trim(line.substr(0, line.find('#'))), "set", rest);
            const auto equals = rest.find('=');
            if (pattern != std::string::npos && equals != std::string::npos)
              {
                const std::string name  = dealii::Utilities::trim(rest.substr(0, equals));
                const std::string value = dealii::Utilities::trim(rest.substr(equals + 1));
                AssertThrow(
                  false,
                  dealii::ExcMessage(
                    "The parameter <" +
                    (source.section.empty() ? name : source.section + "/" + name) + "> = <" +
                    value + "> (" + where + ") does not match its pattern; accepted: " +
                    dealii::Utilities::trim(message.substr(pattern + pattern_text.size())) + "."));
              }
            message = dealii::Utilities::trim(message.substr(end));
            AssertThrow(false,
                        dealii::ExcMessage("In " + where +
                                           (source.section.empty() ?
                                              std::string() :
                                              ", subsection <" + source.section + ">") +
                                           ": " + message));
          }
      }
    } // namespace

    void
    parse_partially(dealii::ParameterHandler &prm, const std::string &filename)
    {
      parse(prm, filename, /*skip_undefined=*/true);
    }

    void
    parse_file(dealii::ParameterHandler &prm, const std::string &filename)
    {
      parse(prm, filename, /*skip_undefined=*/false);
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
    choose_time_step(const double       requested,
                     const double       safety_factor,
                     const double       stable_dt,
                     const std::string &limited_by)
    {
      if (requested <= 0.)
        return safety_factor * stable_dt;
      AssertThrow(requested <= stable_dt,
                  dealii::ExcMessage("The parameter <Time stepping/Time step> = " +
                                     format_number(requested) + " s exceeds the stable limit " +
                                     format_number(stable_dt) + " s of " + limited_by +
                                     "; accepted: 0 (automatic) or a "
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
