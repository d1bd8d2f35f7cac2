// ---------------------------------------------------------------------
// PeriDeal: named geometric regions read from a parameter file.
// ---------------------------------------------------------------------
#ifndef perideal_base_region_h
#define perideal_base_region_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/grid/tria.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief A named region of space: a box, a ball (a disk in 2D), a cylinder (3D), or the cells
   * of a gmsh mesh with a given material id.
   *
   * Regions define where particles are generated, where boundary conditions act and which
   * particles a statistic sums over. Containment is closed with a relative tolerance of 1e-10
   * of the region's size, so lattice points on a face belong to the region.
   */
  template <int dim>
  class Region
  {
  public:
    /// The shapes a region may have (its entry <Shape>).
    enum class Shape
    {
      box,
      ball,
      cylinder,
      mesh
    };

    /**
     * @brief Declare the entries of one region (inside its own subsection).
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read the region called @p name; checks every entry and that a mesh file exists.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &name);

    /**
     * @brief Whether @p p lies in the region.
     */
    bool
    contains(const dealii::Point<dim> &p) const;

    /**
     * @brief A box that holds the whole region.
     */
    const dealii::BoundingBox<dim> &
    bounding_box() const;

    /**
     * @brief The name of the region in the parameter file.
     */
    const std::string &
    name() const;

  private:
    std::string              region_name;
    Shape                    shape = Shape::box;
    dealii::BoundingBox<dim> box;
    dealii::Point<dim>       center;
    dealii::Tensor<1, dim>   axis;
    double                   radius    = 0.;
    double                   tolerance = 0.;

    std::shared_ptr<dealii::Triangulation<dim>>    mesh;
    std::shared_ptr<dealii::GridTools::Cache<dim>> mesh_cache;
    dealii::types::material_id                     material_id = 0;
  };

  /**
   * @brief All regions of a parameter file: subsection "Regions" with an entry "Names" and one
   * subsection per name.
   */
  template <int dim>
  class RegionCollection
  {
  public:
    /**
     * @brief Declare the entry "Names" of subsection "Regions" (first pass).
     */
    static void
    declare_names(dealii::ParameterHandler &prm);

    /**
     * @brief Declare "Names" and one subsection for each of @p names (second pass).
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm, const std::vector<std::string> &names);

    /**
     * @brief Read the names declared in the first pass.
     */
    static std::vector<std::string>
    parse_names(dealii::ParameterHandler &prm);

    /**
     * @brief Read every region.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief The region called @p name; the error names @p entry and the regions that exist.
     */
    const Region<dim> &
    get(const std::string &name, const std::string &entry) const;

    /**
     * @brief Whether a point lies in any of the regions @p names (named by @p entry in errors);
     * an empty function for an empty list.
     */
    std::function<bool(const dealii::Point<dim> &)>
    union_of(const std::vector<std::string> &names, const std::string &entry) const;

    /**
     * @brief A box holding all regions @p names (at least one).
     */
    dealii::BoundingBox<dim>
    bounding_box_of(const std::vector<std::string> &names, const std::string &entry) const;

  private:
    std::map<std::string, Region<dim>> regions;
  };
} // namespace perideal

#endif
