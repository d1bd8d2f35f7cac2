// ---------------------------------------------------------------------
// PeriDeal: the parameter reference (doc/parameters/) written from the declarations.
// ---------------------------------------------------------------------
#include <perideal/base/parameter_reference.h>

#include <regex>
#include <sstream>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

namespace perideal
{
  namespace
  {
    using Tree = boost::property_tree::ptree;

    /**
     * The name of a node of deal.II's tree of entries: every character but letters and digits
     * is written there as '_' and two hexadecimal digits (ParameterHandler's mangling).
     */
    std::string
    demangle(const std::string &name)
    {
      std::string result;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_' && i + 2 < name.size())
          {
            result += static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          result += name[i];
      return result;
    }

    /// An entry of the tree has a value; a subsection has none.
    bool
    is_entry(const Tree &node)
    {
      return node.find("value") != node.not_found() &&
             node.find("documentation") != node.not_found();
    }

    /**
     * The unit of an entry with pattern description @p pattern: none for a choice, a switch or a
     * file name; else the first bracket of @p documentation that holds a unit: letters, digits,
     * '^', '/', '*', '.', '-' and blanks with at least one letter, not a number or an interval
     * ("[0, 1]"); "[-]" is dimensionless.
     */
    std::string
    unit_of(const std::string &pattern, const std::string &documentation)
    {
      for (const std::string kind : {"[Selection", "[MultipleSelection", "[Bool", "[FileName"})
        if (pattern.rfind(kind, 0) == 0)
          return "-";
      static const std::regex bracket(R"(\[([^\[\]]*)\])");
      static const std::regex unit(R"([A-Za-z0-9^/*. -]*[A-Za-z][A-Za-z0-9^/*. -]*|-)");
      for (auto it = std::sregex_iterator(documentation.begin(), documentation.end(), bracket);
           it != std::sregex_iterator();
           ++it)
        {
          const std::string content = (*it)[1].str();
          if (std::regex_match(content, unit))
            return content == "-" ? "1 (dimensionless)" : content;
        }
      return "-";
    }

    /// @p text in a Markdown code span (a value may hold backticks of its own).
    std::string
    code(const std::string &text)
    {
      if (text.empty())
        return "(empty)";
      const std::string fence = text.find('`') == std::string::npos ? "`" : "`` ";
      const std::string close = fence == "`" ? "`" : " ``";
      return fence + text + close;
    }

    /**
     * @p text as Markdown text: the angle brackets of the <Section/Entry> names as entities (a
     * Markdown renderer takes <Regions> for an HTML tag and drops it), asterisks escaped.
     */
    std::string
    markdown_text(const std::string &text)
    {
      std::string result;
      for (const char c : text)
        result += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '*' ? "\\*" : std::string(1, c);
      return result;
    }

    void
    write_section(const Tree &section, const std::string &path, std::ostream &out)
    {
      bool heading = false;
      for (const auto &[mangled, node] : section)
        if (is_entry(node))
          {
            if (!heading)
              {
                out << "\n## " << (path.empty() ? "Top level" : code(path)) << "\n\n";
                heading = true;
              }
            const std::string documentation = node.get<std::string>("documentation");
            const std::string pattern       = node.get<std::string>("pattern_description");
            out << "- **" << demangle(mangled) << "**\n"
                << "  - Default: " << code(node.get<std::string>("default_value")) << "\n"
                << "  - Pattern: " << code(pattern) << "\n"
                << "  - Unit: " << unit_of(pattern, documentation) << "\n"
                << "  - "
                << (documentation.empty() ? "(no documentation)" : markdown_text(documentation))
                << "\n";
          }
      for (const auto &[mangled, node] : section)
        if (!is_entry(node))
          write_section(node, path + (path.empty() ? "" : "/") + demangle(mangled), out);
    }
  } // namespace

  void
  write_parameter_reference(const dealii::ParameterHandler &prm,
                            const unsigned int              dim,
                            std::ostream                   &out)
  {
    std::stringstream json;
    prm.print_parameters(json,
                         dealii::ParameterHandler::OutputStyle(
                           dealii::ParameterHandler::JSON |
                           dealii::ParameterHandler::KeepDeclarationOrder));
    Tree tree;
    boost::property_tree::read_json(json, tree);
    const std::string d = std::to_string(dim);
    out << "# Parameter reference, " << d << "D\n\n"
        << "Every entry of a `perideal-solid` parameter file with `set Dimension = " << d
        << "`, generated from the declarations in the code by `perideal-solid "
           "--print-parameter-reference "
        << d
        << "`; do not edit it by hand. After a change of an entry, regenerate it with `cmake "
           "--build build --target parameter_reference` (the test `doc/parameters_"
        << d << "d` compares it with the code).\n\n"
        << "Subsections are listed by their path, in the order of declaration. Regions, "
           "particle boundary conditions and FE boundary conditions take the names listed in "
           "their `Names` entry (`Regions/Names`, `Boundary conditions/Names`, `Finite "
           "elements/Boundary conditions/Names`); `<name>` stands for each of them. A plugin "
           "with entries of its own (a material model, the damage model `critical stretch`, an "
           "FE physics, a coupling method) reads them from a subsection named after it; only "
           "the subsection of the chosen plugin is read.\n\n"
           "Units are SI. The unit of an entry is the first one its documentation states in "
           "brackets (`[-]`: dimensionless); `-` where none applies: choices, switches, names, "
           "counts, and expressions whose unit the text gives.\n";
    write_section(tree, "", out);
  }
} // namespace perideal
