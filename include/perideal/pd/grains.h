// ---------------------------------------------------------------------
// PeriDeal: the grains of a polycrystal, a Voronoi tessellation of seeds with orientations.
// ---------------------------------------------------------------------
#ifndef perideal_pd_grains_h
#define perideal_pd_grains_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief The grains of a polycrystal: the Voronoi cells of seed points read from a file, each
   * with the orientation of its crystal, and the fracture energy of their boundaries.
   *
   * The file (entry <Grains file>) has one grain per line: the seed's dim coordinates [m], then
   * the grain's orientation, the z-x-z Euler angles phi, theta, psi [degrees] in 3D and phi (a
   * rotation about z) in 2D; '#' starts a comment. A point belongs to the grain of its nearest
   * seed (ties: the first seed in the file), so the grains are the seeds' Voronoi cells. A
   * grain's material axes are the material's (its Orientation entry) rotated by the grain's
   * angles about the global axes: axes_g = R(grain) axes. Without a file the body is one grain
   * of rotation 1.
   *
   * A bond between two grains is a grain-boundary bond; <Grain boundary fracture energy ratio>
   * is the ratio of its critical energy to that of a bond of the same direction inside the
   * grains (the mean of the two grains').
   */
  template <int dim>
  class Grains
  {
  public:
    /**
     * @brief Declare <Grains file> and <Grain boundary fracture energy ratio> in the current
     * subsection.
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read the entries of the current subsection, whose path @p section names them in
     * errors, and the file (every line checked before any heavy work).
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &section);

    /// The number of grains (1 without a file).
    unsigned int
    size() const;

    /// Whether a <Grains file> is given (the particles are then a polycrystal).
    bool
    has_file() const;

    /// The rotation of grain @p g (applied to the material's axes).
    const dealii::Tensor<2, 3> &
    rotation(const unsigned int g) const;

    /// The grain of point @p x: the index of the nearest seed.
    unsigned int
    grain_of(const dealii::Point<dim> &x) const;

    /// The ratio of a grain-boundary bond's critical energy to the grains'.
    double
    boundary_ratio() const;

    /// One line for the log (empty without a file).
    std::string
    summary() const;

  private:
    std::string                       file;
    std::vector<dealii::Point<dim>>   seeds;
    std::vector<dealii::Tensor<2, 3>> rotations;
    double                            ratio = 1.;
  };
} // namespace perideal

#endif
