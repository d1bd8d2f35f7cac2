// ---------------------------------------------------------------------
// PeriDeal: the grains of a polycrystal, a Voronoi tessellation of seeds with orientations.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>

#include <perideal/base/elasticity.h>
#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/grains.h>

#include <fstream>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  Grains<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Grains file",
                      "",
                      Patterns::Anything(),
                      std::string("A polycrystal: a text file with one grain per line, the seed "
                                  "point's coordinates (m) and the grain's orientation (") +
                        (dim == 3 ? "z-x-z Euler angles phi, theta, psi" :
                                    "phi, a rotation about z") +
                        " in degrees), '#' starts a comment; relative to the working directory. "
                        "A particle belongs to the grain of its nearest seed (Voronoi cells); "
                        "a grain's material axes are the material's (Orientation) rotated by "
                        "the grain's angles about the global axes. Empty: one grain.");
    prm.declare_entry("Grain boundary fracture energy ratio",
                      "1",
                      Patterns::Double(),
                      "The critical energy of a bond between two grains over that of a bond of "
                      "the same direction inside them (the mean of the two grains'); > 0.");
  }

  template <int dim>
  void
  Grains<dim>::parse_parameters(ParameterHandler &prm, const std::string &section)
  {
    file  = prm.get("Grains file");
    ratio = prm.get_double("Grain boundary fracture energy ratio");
    ParameterUtilities::require_positive(ratio, section + "/Grain boundary fracture energy ratio");
    seeds.clear();
    rotations.clear();
    if (file.empty())
      {
        seeds.emplace_back();
        rotations.push_back(rotation_from_euler_angles(0., 0., 0.));
        return;
      }
    std::ifstream in(file);
    AssertThrow(in,
                ExcMessage("<" + section + "/Grains file> = " + file +
                           " names no readable file (paths are relative to the working "
                           "directory)."));
    const unsigned int n_angles = dim == 3 ? 3 : 1;
    const std::string  expected = std::to_string(dim) + " coordinates and " +
                                 std::to_string(n_angles) +
                                 (dim == 3 ? " angles (phi theta psi)" : " angle (phi)");
    std::string line;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        line = line.substr(0, line.find('#'));
        std::istringstream  words(line);
        std::vector<double> values;
        std::string         word;
        while (words >> word)
          {
            std::size_t end = 0;
            double      value;
            try
              {
                value = std::stod(word, &end);
              }
            catch (const std::exception &)
              {
                end = 0;
              }
            AssertThrow(end == word.size() && std::isfinite(value),
                        ExcMessage("<" + section + "/Grains file> " + file + ", line " +
                                   std::to_string(number) + ": '" + word +
                                   "' is not a number; each line holds " + expected + "."));
            values.push_back(value);
          }
        if (values.empty())
          continue;
        AssertThrow(values.size() == dim + n_angles,
                    ExcMessage("<" + section + "/Grains file> " + file + ", line " +
                               std::to_string(number) + ": " + std::to_string(values.size()) +
                               " numbers; each line holds " + expected + "."));
        Point<dim> seed;
        for (unsigned int d = 0; d < dim; ++d)
          seed[d] = values[d];
        seeds.push_back(seed);
        rotations.push_back(dim == 3 ? rotation_from_euler_angles(values[3], values[4], values[5]) :
                                       rotation_from_euler_angles(values[2], 0., 0.));
      }
    AssertThrow(!seeds.empty(),
                ExcMessage("<" + section + "/Grains file> " + file +
                           " holds no grain; each line holds " + expected + "."));
  }

  template <int dim>
  unsigned int
  Grains<dim>::size() const
  {
    return seeds.size();
  }

  template <int dim>
  bool
  Grains<dim>::has_file() const
  {
    return !file.empty();
  }

  template <int dim>
  const Tensor<2, 3> &
  Grains<dim>::rotation(const unsigned int g) const
  {
    return rotations[g];
  }

  template <int dim>
  unsigned int
  Grains<dim>::grain_of(const Point<dim> &x) const
  {
    unsigned int nearest  = 0;
    double       distance = std::numeric_limits<double>::infinity();
    for (unsigned int g = 0; g < seeds.size(); ++g)
      if (const double d = x.distance_square(seeds[g]); d < distance)
        {
          distance = d;
          nearest  = g;
        }
    return nearest;
  }

  template <int dim>
  double
  Grains<dim>::boundary_ratio() const
  {
    return ratio;
  }

  template <int dim>
  std::string
  Grains<dim>::summary() const
  {
    if (file.empty())
      return "";
    return std::to_string(seeds.size()) + " grains (Voronoi cells of the seeds of " + file +
           "), grain-boundary fracture energy ratio " + ParameterUtilities::format_number(ratio);
  }

  template class Grains<2>;
  template class Grains<3>;
} // namespace perideal
