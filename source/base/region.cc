// ---------------------------------------------------------------------
// PeriDeal: named geometric regions read from a parameter file.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/boost_adaptors/bounding_box.h>
#include <deal.II/boost_adaptors/point.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/region.h>

#include <filesystem>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // The shapes by their names in <Regions/<name>/Shape>.
    template <int dim>
    const ParameterUtilities::Choices<typename Region<dim>::Shape> &
    shapes()
    {
      using Shape                                           = typename Region<dim>::Shape;
      static const ParameterUtilities::Choices<Shape> names = {{"box", Shape::box},
                                                               {"ball", Shape::ball},
                                                               {"cylinder", Shape::cylinder},
                                                               {"mesh", Shape::mesh}};
      return names;
    }
  } // namespace

  template <int dim>
  void
  Region<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Shape",
                      "box",
                      Patterns::Selection(ParameterUtilities::selection(shapes<dim>())),
                      "The kind of region: 'box' (axis-aligned, Lower/Upper corner), 'ball' "
                      "(disk in 2D, sphere in 3D: Center, Radius), 'cylinder' (3D only: Center of "
                      "the base, Axis vector whose length is the height, Radius), 'mesh' (cells "
                      "of a gmsh mesh with the given Material id).");
    const std::string zero = (dim == 2 ? "0, 0" : "0, 0, 0");
    prm.declare_entry("Lower corner", zero, Patterns::Anything(), "Box: lowest corner [m].");
    prm.declare_entry("Upper corner", zero, Patterns::Anything(), "Box: highest corner [m].");
    prm.declare_entry("Center", zero, Patterns::Anything(), "Ball, cylinder: center [m].");
    prm.declare_entry("Axis",
                      zero,
                      Patterns::Anything(),
                      "Cylinder: axis from the center of the base to the center of the top [m].");
    prm.declare_entry("Radius", "0", Patterns::Double(0.), "Ball, cylinder: radius [m].");
    prm.declare_entry("Mesh file",
                      "",
                      Patterns::Anything(),
                      "Mesh: a gmsh .msh file (relative to the working directory); lengths in m.");
    prm.declare_entry("Material id",
                      "0",
                      Patterns::Integer(0, 255),
                      "Mesh: the material id (gmsh physical tag of the surface/volume) of the "
                      "cells that form the region.");
  }

  template <int dim>
  void
  Region<dim>::parse_parameters(ParameterHandler &prm, const std::string &name)
  {
    region_name              = name;
    const std::string prefix = "Regions/" + name + "/";
    shape = ParameterUtilities::choice(shapes<dim>(), prm.get("Shape"), prefix + "Shape");
    if (shape == Shape::box)
      {
        const auto lower =
          ParameterUtilities::parse_point<dim>(prm.get("Lower corner"), prefix + "Lower corner");
        const auto upper =
          ParameterUtilities::parse_point<dim>(prm.get("Upper corner"), prefix + "Upper corner");
        for (unsigned int d = 0; d < dim; ++d)
          AssertThrow(upper[d] > lower[d],
                      ExcMessage("The parameter <" + prefix +
                                 "Upper corner> must exceed <Lower corner> in every coordinate."));
        box = BoundingBox<dim>(std::make_pair(lower, upper));
      }
    else if (shape == Shape::ball || shape == Shape::cylinder)
      {
        center = ParameterUtilities::parse_point<dim>(prm.get("Center"), prefix + "Center");
        radius = prm.get_double("Radius");
        ParameterUtilities::require_positive(radius, prefix + "Radius");
        Point<dim> lower = center, upper = center;
        if (shape == Shape::cylinder)
          {
            AssertThrow(dim == 3,
                        ExcMessage("The parameter <" + prefix +
                                   "Shape> = cylinder exists in 3D only; use 'ball' (a disk) or "
                                   "'box' in 2D."));
            axis = ParameterUtilities::parse_point<dim>(prm.get("Axis"), prefix + "Axis");
            ParameterUtilities::require_positive(axis.norm(), prefix + "Axis (its length)");
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = std::min(center[d], center[d] + axis[d]) - radius;
                upper[d] = std::max(center[d], center[d] + axis[d]) + radius;
              }
          }
        else
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] -= radius;
              upper[d] += radius;
            }
        box = BoundingBox<dim>(std::make_pair(lower, upper));
      }
    else
      {
        const std::string file_name = prm.get("Mesh file");
        AssertThrow(std::filesystem::exists(file_name),
                    ExcMessage("The parameter <" + prefix + "Mesh file> = <" + file_name +
                               "> names a file that does not exist."));
        material_id = prm.get_integer("Material id");
        mesh        = std::make_shared<Triangulation<dim>>();
        GridIn<dim> grid_in(*mesh);
        grid_in.read(file_name);
        mesh_cache = std::make_shared<GridTools::Cache<dim>>(*mesh);
        bool found = false;
        for (const auto &cell : mesh->active_cell_iterators())
          if (cell->material_id() == material_id)
            {
              const auto cell_box = cell->bounding_box();
              if (!found)
                box = cell_box;
              else
                box.merge_with(cell_box);
              found = true;
            }
        AssertThrow(found,
                    ExcMessage("The mesh <" + file_name + "> has no cell with the material id " +
                               std::to_string(material_id) + " given by <" + prefix +
                               "Material id>."));
      }
    double size = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      size = std::max(size, box.side_length(d));
    tolerance = 1e-10 * size;
  }

  template <int dim>
  bool
  Region<dim>::contains(const Point<dim> &p) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (p[d] < box.lower_bound(d) - tolerance || p[d] > box.upper_bound(d) + tolerance)
        return false;
    switch (shape)
      {
        case Shape::box:
          return true;
        case Shape::ball:
          return p.distance(center) <= radius + tolerance;
        case Shape::cylinder:
          {
            const Tensor<1, dim> r      = p - center;
            const double         length = axis.norm();
            const double         along  = r * axis / length;
            if (along < -tolerance || along > length + tolerance)
              return false;
            return (r - along * axis / length).norm() <= radius + tolerance;
          }
        case Shape::mesh:
          {
            // No cell's bounding box near p: outside at once (deal.II's search would try every
            // cell before it gives up, e.g. for each lattice point in a hole of the mesh).
            Point<dim> low = p, high = p;
            for (unsigned int d = 0; d < dim; ++d)
              {
                low[d] -= tolerance;
                high[d] += tolerance;
              }
            const auto &tree = mesh_cache->get_cell_bounding_boxes_rtree();
            if (tree.qbegin(boost::geometry::index::intersects(
                  BoundingBox<dim>(std::make_pair(low, high)))) == tree.qend())
              return false;
            const auto found = GridTools::find_active_cell_around_point(*mesh_cache, p);
            return found.first.state() == IteratorState::valid &&
                   found.first->material_id() == material_id;
          }
      }
    return false;
  }

  template <int dim>
  const BoundingBox<dim> &
  Region<dim>::bounding_box() const
  {
    return box;
  }

  template <int dim>
  const std::string &
  Region<dim>::name() const
  {
    return region_name;
  }

  template <int dim>
  void
  RegionCollection<dim>::declare_names(ParameterHandler &prm)
  {
    ParameterUtilities::declare_name_list(
      prm,
      "Regions",
      "Comma-separated names of the regions defined below, each in a subsection of its own name. "
      "Regions are referred to by name elsewhere (body, boundary conditions).");
  }

  template <int dim>
  void
  RegionCollection<dim>::declare_parameters(ParameterHandler               &prm,
                                            const std::vector<std::string> &names)
  {
    declare_names(prm);
    prm.enter_subsection("Regions");
    for (const std::string &name : names)
      {
        prm.enter_subsection(name);
        Region<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  template <int dim>
  std::vector<std::string>
  RegionCollection<dim>::parse_names(ParameterHandler &prm)
  {
    return ParameterUtilities::parse_name_list(prm, "Regions");
  }

  template <int dim>
  void
  RegionCollection<dim>::parse_parameters(ParameterHandler &prm)
  {
    regions.clear();
    const auto names = parse_names(prm);
    prm.enter_subsection("Regions");
    for (const std::string &name : names)
      {
        prm.enter_subsection(name);
        regions[name].parse_parameters(prm, name);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  template <int dim>
  const Region<dim> &
  RegionCollection<dim>::get(const std::string &name, const std::string &entry) const
  {
    const auto it = regions.find(name);
    if (it == regions.end())
      {
        std::string known;
        for (const auto &r : regions)
          known += (known.empty() ? "" : ", ") + r.first;
        AssertThrow(false,
                    ExcMessage("The parameter <" + entry + "> names the region <" + name +
                               ">, which is not defined. Defined in <Regions/Names>: " + known +
                               "."));
      }
    return it->second;
  }

  template <int dim>
  std::function<bool(const Point<dim> &)>
  RegionCollection<dim>::union_of(const std::vector<std::string> &names,
                                  const std::string              &entry) const
  {
    if (names.empty())
      return {};
    std::vector<const Region<dim> *> members;
    for (const auto &name : names)
      members.push_back(&get(name, entry));
    return [members](const Point<dim> &p) {
      for (const auto *region : members)
        if (region->contains(p))
          return true;
      return false;
    };
  }

  template <int dim>
  BoundingBox<dim>
  RegionCollection<dim>::bounding_box_of(const std::vector<std::string> &names,
                                         const std::string              &entry) const
  {
    AssertThrow(!names.empty(), ExcMessage("The parameter <" + entry + "> names no region."));
    BoundingBox<dim> box = get(names[0], entry).bounding_box();
    for (const auto &name : names)
      box.merge_with(get(name, entry).bounding_box());
    return box;
  }

  template class Region<2>;
  template class Region<3>;
  template class RegionCollection<2>;
  template class RegionCollection<3>;
} // namespace perideal
