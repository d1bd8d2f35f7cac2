// ---------------------------------------------------------------------
// PeriDeal: the parameter reference (doc/parameters/) written from the declarations.
// ---------------------------------------------------------------------
#ifndef perideal_base_parameter_reference_h
#define perideal_base_parameter_reference_h

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>

namespace perideal
{
  /**
   * @brief Write every entry declared in @p prm as Markdown, in the manner of the parameter
   * references of ASPECT and Lethe: one heading per subsection (its path, e.g.
   * `Material/bond based`), in the order of declaration, and per entry its name, default value,
   * pattern (deal.II's description of the accepted values), unit and documentation.
   *
   * The unit is the first bracket of the documentation that holds a unit, e.g. "[kg/m^3]" or
   * "[-]" (dimensionless); "-" for a choice, a switch or a file name, and for an entry whose
   * documentation states none (a count, a name, an expression whose unit the text gives). The
   * document starts with a title and an introduction for the parameter files of dimension
   * @p dim (`perideal-solid --print-parameter-reference dim`). The output depends only on the
   * declarations, so that a test can compare it with the committed reference (doc/parameters/).
   */
  void
  write_parameter_reference(const dealii::ParameterHandler &prm,
                            const unsigned int              dim,
                            std::ostream                   &out);
} // namespace perideal

#endif
