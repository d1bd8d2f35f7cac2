// ---------------------------------------------------------------------
// PeriDeal: the PD region follows the crack (where FE cells become particles during a run).
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/adaptive_region.h>
#include <perideal/pd/damage_model.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // The directions in which the damage criterion looks for the edge of the PD-only zone: 16
    // in the plane, the 26 neighbours of a cube cell in 3D.
    template <int dim>
    std::vector<Tensor<1, dim>>
    edge_directions()
    {
      std::vector<Tensor<1, dim>> directions;
      if (dim == 2)
        for (unsigned int k = 0; k < 16; ++k)
          {
            Tensor<1, dim> n;
            n[0] = std::cos(k * numbers::PI / 8.);
            n[1] = std::sin(k * numbers::PI / 8.);
            directions.push_back(n);
          }
      else
        for (int i = -1; i <= 1; ++i)
          for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k)
              if (i != 0 || j != 0 || k != 0)
                {
                  Tensor<1, dim> n;
                  n[0]       = i;
                  n[1]       = j;
                  n[dim - 1] = k;
                  directions.push_back(n / n.norm());
                }
      return directions;
    }
  } // namespace

  template <int dim>
  void
  AdaptiveRegion<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Adaptive region");
    prm.declare_entry("Criterion",
                      "none",
                      Patterns::Selection(
                        "none|principal strain|damage|principal strain and damage"),
                      "Blended runs, explicit or by quasi-static load steps: what converts FE "
                      "cells into particles during the run (the PD region grows by disks, balls "
                      "in 3D, of <Core radius> around the points it flags, with an overlap of "
                      "<Ramp width>). 'principal strain': the centre of an FE cell whose largest "
                      "principal strain (the slope of a scalar field) exceeds <Strain fraction> "
                      "times the critical stretch; 'damage': a particle with damage >= <Damage "
                      "threshold> within <Damage distance> of the edge of the PD-only zone; "
                      "'none': the region is fixed.");
    prm.declare_entry("Check interval",
                      "10",
                      Patterns::Integer(),
                      "Time steps (load steps of a quasi-static run) between two checks of the "
                      "criterion (at least 1).");
    prm.declare_entry("Strain fraction",
                      "0.5",
                      Patterns::Double(),
                      "Criterion 'principal strain': the fraction of the critical stretch of "
                      "<Material/Damage model> above which an FE cell is converted, in (0, 1]. "
                      "The critical stretch is the bonds' elastic limit, the stretch at which "
                      "they leave the linear law: where a brittle bond breaks, and where a "
                      "softening bond starts to soften (the log's 'Critical stretch'). For "
                      "<Material/Model> = timoshenko bond based with <Failure law> = softening "
                      "it is the axial limit s_0: sigma_t / E with a <Tensile strength>, "
                      "otherwise the s_0 that G_0 and k give; the bonds carry their full force "
                      "up to it and dissipate G_0 only well beyond it. With the fraction 1 a "
                      "cell converts when the bond along its largest principal strain reaches "
                      "s_0 (in a uniform strain the largest stretch of a bond is that strain); "
                      "a fraction below 1 converts the cells before their bonds soften.");
    prm.declare_entry("Strain region",
                      "1",
                      Patterns::Anything(),
                      "Criterion 'principal strain': where FE cells may be converted, a function "
                      "of x, y (z) that is > 0 there (the centre of the cell counts); '1': "
                      "everywhere. It keeps the PD zone away from a strain concentration that the "
                      "PD model would not change, such as the edge of an FE boundary condition "
                      "(a disk that would reach one stops the run).");
    prm.declare_entry("Damage threshold",
                      "0.3",
                      Patterns::Double(),
                      "Criterion 'damage': the damage of a particle that flags its position, in "
                      "(0, 1).");
    prm.declare_entry("Damage distance",
                      "0",
                      Patterns::Double(),
                      "Criterion 'damage': a damaged particle closer than this to the edge of the "
                      "PD-only zone (beta < 1) flags its position [m]; > 0 and smaller than <Core "
                      "radius>.");
    prm.declare_entry("Lead distance",
                      "0",
                      Patterns::Double(),
                      "Criterion 'damage': the new disk is centred this far beyond the flagged "
                      "particle, away from the centre of the nearest disk (the way the crack "
                      "runs), so that the PD zone leads the crack tip and fewer conversions are "
                      "needed; 0 centres it on the particle [m]. In [0, <Core radius> - <Damage "
                      "distance>] (the particle then lies at least <Damage distance> inside the "
                      "new PD-only zone). A centre outside the body falls back to the particle.");
    prm.declare_entry("Core radius",
                      "0",
                      Patterns::Double(),
                      "Radius of the PD-only disk (ball) around a flagged point [m]: the buffer "
                      "that keeps the PD zone ahead of a crack tip; > 0. It should hold a few FE "
                      "cells (a cell carries no FE unknowns only where beta = 1 on all of it) and "
                      "a few horizons.");
    prm.declare_entry("Ramp width",
                      "0",
                      Patterns::Double(),
                      "Width of the overlap around the disks, where beta falls from 1 to 0 [m]; at "
                      "least a horizon (the blended coupling needs an overlap a horizon wide).");
    prm.declare_entry("Seed shape",
                      "ball",
                      Patterns::Selection("ball|cylinder"),
                      "The PD-only zone around a seed: 'ball' (a disk in 2D); 'cylinder' (3D "
                      "only): a cylinder of radius <Core radius> whose axis passes through the "
                      "seed parallel to z, through the whole body (a crack through the thickness "
                      "of a plate); the seed's z is then irrelevant.");
    prm.declare_entry("Initial seeds",
                      "",
                      Patterns::Anything(),
                      "Points whose disks are PD from the start, in addition to <Coupling/Blending "
                      "function> (e.g. the notch tips: '0.05, 0.025; 0.05, -0.025'); empty: "
                      "none.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  AdaptiveRegion<dim>::parse_parameters(ParameterHandler &prm, const double horizon)
  {
    prm.enter_subsection("Adaptive region");
    const std::string section = "Coupling/Adaptive region/";
    const auto        refuse  = [&](const std::string &entry, const std::string &accepted) {
      AssertThrow(false,
                  ExcMessage("The parameter <" + section + entry + "> is " + prm.get(entry) +
                             "; accepted values are " + accepted + "."));
    };
    const std::string name = prm.get("Criterion");
    criterion              = name == "none"             ? Criterion::none :
                             name == "principal strain" ? Criterion::principal_strain :
                             name == "damage"           ? Criterion::damage :
                                                          Criterion::principal_strain_and_damage;
    const long check       = prm.get_integer("Check interval");
    if (check < 1)
      refuse("Check interval", "integers >= 1 (time steps between two checks)");
    interval        = static_cast<unsigned int>(check);
    strain_fraction = prm.get_double("Strain fraction");
    if (!(strain_fraction > 0. && strain_fraction <= 1.))
      refuse("Strain fraction", "in (0, 1]");
    strain_region    = ParameterUtilities::make_function<dim>(prm.get("Strain region"),
                                                           1,
                                                           section + "Strain region");
    damage_threshold = prm.get_double("Damage threshold");
    if (!(damage_threshold > 0. && damage_threshold < 1.))
      refuse("Damage threshold", "in (0, 1)");
    core_radius     = prm.get_double("Core radius");
    damage_distance = prm.get_double("Damage distance");
    ramp_width      = prm.get_double("Ramp width");
    lead_distance   = prm.get_double("Lead distance");
    if (enabled())
      {
        if (!(core_radius > 0.))
          refuse("Core radius", "> 0 [m] (a few horizons, and a few FE cells)");
        if (!(ramp_width >= horizon))
          refuse("Ramp width",
                 ">= the horizon, " + ParameterUtilities::format_number(horizon) + " m");
        if (criterion != Criterion::principal_strain &&
            !(damage_distance > 0. && damage_distance < core_radius))
          refuse("Damage distance",
                 "> 0 and smaller than <Core radius> = " + prm.get("Core radius") + " m");
        if (!(lead_distance >= 0. && lead_distance <= core_radius - damage_distance))
          refuse("Lead distance",
                 "in [0, <Core radius> - <Damage distance>] = [0, " +
                   ParameterUtilities::format_number(core_radius - damage_distance) + "] m");
      }
    shape = prm.get("Seed shape") == "cylinder" ? SeedShape::cylinder : SeedShape::ball;
    if (shape == SeedShape::cylinder && dim != 3)
      refuse("Seed shape",
             "'ball' in 2D (a disk; 'cylinder' is a 3D shape whose axis is parallel to z)");
    bin_width = core_radius + ramp_width + 2. * horizon;
    seeds.clear();
    projected_seeds.clear();
    std::vector<Point<dim>> initial;
    for (const auto &item : Utilities::split_string_list(prm.get("Initial seeds"), ';'))
      if (!item.empty())
        initial.push_back(ParameterUtilities::parse_point<dim>(item, section + "Initial seeds"));
    AssertThrow(initial.empty() || enabled(),
                ExcMessage("<" + section + "Initial seeds> is given, but <" + section +
                           "Criterion> is none: choose a criterion, or give the initial PD zone "
                           "by <Coupling/Blending function>."));
    add_seeds(initial);
    prm.leave_subsection();
  }

  template <int dim>
  bool
  AdaptiveRegion<dim>::enabled() const
  {
    return criterion != Criterion::none;
  }

  template <int dim>
  unsigned int
  AdaptiveRegion<dim>::check_interval() const
  {
    return interval;
  }

  template <int dim>
  const std::vector<Point<dim>> &
  AdaptiveRegion<dim>::seed_points() const
  {
    return seeds;
  }

  template <int dim>
  void
  AdaptiveRegion<dim>::add_seeds(const std::vector<Point<dim>> &new_seeds)
  {
    seeds.insert(seeds.end(), new_seeds.begin(), new_seeds.end());
    for (const auto &s : new_seeds)
      projected_seeds.push_back(project(s));
    if (!seeds.empty())
      seed_cells.reinit(make_array_view(projected_seeds), bin_width);
  }

  template <int dim>
  typename AdaptiveRegion<dim>::SeedShape
  AdaptiveRegion<dim>::seed_shape() const
  {
    return shape;
  }

  template <int dim>
  Point<dim>
  AdaptiveRegion<dim>::project(const Point<dim> &x) const
  {
    Point<dim> p = x;
    if (shape == SeedShape::cylinder)
      p[dim - 1] = 0.;
    return p;
  }

  template <int dim>
  double
  AdaptiveRegion<dim>::seed_distance(const Point<dim> &x, const Point<dim> &s) const
  {
    return project(x).distance(project(s));
  }

  template <int dim>
  double
  AdaptiveRegion<dim>::nearest_seed(const Point<dim> &x, unsigned int *index) const
  {
    // Every seed within a bin width of x lies in the 3^dim bins around x's.
    double       nearest = std::numeric_limits<double>::max();
    unsigned int first   = numbers::invalid_unsigned_int;
    if (seeds.empty())
      return nearest;
    const Point<dim> y = project(x);
    seed_cells.for_each_near(y, [&](const unsigned int s) {
      const double distance = y.distance(projected_seeds[s]);
      if (distance < nearest || (distance == nearest && s < first))
        {
          nearest = distance;
          first   = s;
        }
    });
    if (index != nullptr && first != numbers::invalid_unsigned_int)
      *index = first;
    return nearest;
  }

  template <int dim>
  double
  AdaptiveRegion<dim>::disk_blending(const double distance) const
  {
    return std::clamp((core_radius + ramp_width - distance) / ramp_width, 0., 1.);
  }

  template <int dim>
  double
  AdaptiveRegion<dim>::blending(const Point<dim> &x) const
  {
    return disk_blending(nearest_seed(x));
  }

  template <int dim>
  bool
  AdaptiveRegion<dim>::within_reach(const Point<dim> &x, const double reach) const
  {
    Assert(core_radius + ramp_width + reach <= bin_width, ExcInternalError());
    return nearest_seed(x) < core_radius + ramp_width + reach;
  }

  template <int dim>
  std::vector<Point<dim>>
  AdaptiveRegion<dim>::propose_seeds(const CoupledState<dim>                         &state,
                                     const std::function<double(const Point<dim> &)> &beta,
                                     const std::function<bool(const Point<dim> &)>   &in_body,
                                     const std::vector<double> &precrack_damage,
                                     const std::string         &when) const
  {
    std::vector<double> flagged; // coordinates of the points this rank flags
    const auto          flag = [&](const Point<dim> &x) {
      for (unsigned int d = 0; d < dim; ++d)
        flagged.push_back(x[d]);
    };

    // FE cells whose principal strain exceeds the fraction of the critical stretch.
    const auto &fe = state.fe();
    if ((criterion == Criterion::principal_strain ||
         criterion == Criterion::principal_strain_and_damage) &&
        fe.n_dofs() > 0)
      {
        const double         limit = strain_fraction * state.pd().critical_stretch();
        const MappingQ1<dim> mapping;
        Point<dim>           unit_centre;
        for (unsigned int d = 0; d < dim; ++d)
          unit_centre[d] = 0.5;
        FEValues<dim> values(mapping,
                             fe.get_fe_collection()[0],
                             Quadrature<dim>(unit_centre),
                             update_gradients | update_quadrature_points);
        const bool    is_scalar = fe.field_layout().kind(0) == ComponentKind::scalar;
        std::vector<SymmetricTensor<2, dim>> strain(1);
        std::vector<Tensor<1, dim>>          slope(1);
        state.U.update_ghost_values();
        for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
          if (cell->is_locally_owned() && cell->active_fe_index() == 0)
            {
              values.reinit(cell);
              double measure = 0.;
              if (is_scalar)
                {
                  values[FEValuesExtractors::Scalar(0)].get_function_gradients(state.U, slope);
                  measure = slope[0].norm();
                }
              else
                {
                  values[FEValuesExtractors::Vector(0)].get_function_symmetric_gradients(state.U,
                                                                                         strain);
                  measure = eigenvalues(strain[0])[0];
                }
              // A cell already inside the PD-only zone of a disk needs no other.
              if (measure > limit && beta(values.quadrature_point(0)) < 1. &&
                  strain_region->value(values.quadrature_point(0)) > 0.)
                flag(values.quadrature_point(0));
            }
      }

    // Damaged particles near the edge of the PD-only zone.
    if (criterion == Criterion::damage || criterion == Criterion::principal_strain_and_damage)
      {
        const auto &ps         = state.pd().particles();
        const auto &x          = ps.positions();
        const auto  damage     = damage_index(ps);
        const auto  directions = edge_directions<dim>();
        // The damaged particle farthest out in the overlap, and where it is.
        double     least_beta = 1.;
        Point<dim> where;
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          if (damage[i] - precrack_damage[i] >= damage_threshold)
            {
              if (const double b = beta(x[i]); b < least_beta)
                {
                  least_beta = b;
                  where      = x[i];
                }
              // (beta first: the body test may be a point search in a mesh.)
              bool near_edge = false;
              for (const double r : {0.5 * damage_distance, damage_distance})
                for (const auto &n : directions)
                  {
                    const Point<dim> y = x[i] + r * n;
                    near_edge          = near_edge || (beta(y) < 1. && in_body(y));
                  }
              if (!near_edge)
                continue;
              // Ahead of the particle, away from the nearest disk's centre.
              unsigned int nearest = 0;
              Point<dim>   centre  = x[i];
              if (lead_distance > 0. &&
                  nearest_seed(x[i], &nearest) < std::numeric_limits<double>::max())
                {
                  const Tensor<1, dim> away = project(x[i]) - projected_seeds[nearest];
                  const double         norm = away.norm();
                  if (norm > 0.)
                    centre += (lead_distance / norm) * away;
                  if (!in_body(centre))
                    centre = x[i];
                }
              flag(centre);
            }
        check_crack_inside(least_beta, where, state.comm(), when);
      }

    // The same list on every rank, in lexicographic order, thinned to one point per R/2.
    const auto              all = Utilities::MPI::all_gather(state.comm(), flagged);
    std::vector<Point<dim>> points;
    for (const auto &part : all)
      for (std::size_t k = 0; k + dim <= part.size(); k += dim)
        {
          Point<dim> p;
          for (unsigned int d = 0; d < dim; ++d)
            p[d] = part[k + d];
          points.push_back(p);
        }
    std::sort(points.begin(), points.end(), [](const Point<dim> &a, const Point<dim> &b) {
      for (unsigned int d = 0; d < dim; ++d)
        if (a[d] != b[d])
          return a[d] < b[d];
      return false;
    });
    std::vector<Point<dim>> kept;
    for (const auto &p : points)
      if (std::none_of(kept.begin(), kept.end(), [&](const Point<dim> &q) {
            return seed_distance(p, q) < 0.5 * core_radius;
          }))
        kept.push_back(p);
    return kept;
  }

  template <int dim>
  void
  AdaptiveRegion<dim>::check_crack_inside(const double       least_beta,
                                          const Point<dim>  &where,
                                          const MPI_Comm     comm,
                                          const std::string &when) const
  {
    // The least beta of all ranks, and the point of the first rank that holds it.
    const double least = Utilities::MPI::min(least_beta, comm);
    if (least >= 1.)
      return;
    std::vector<double> mine = {least_beta};
    for (unsigned int d = 0; d < dim; ++d)
      mine.push_back(where[d]);
    const auto all   = Utilities::MPI::all_gather(comm, mine);
    const auto first = std::find_if(all.begin(), all.end(), [&](const std::vector<double> &item) {
      return item[0] == least;
    });
    std::ostringstream point;
    for (unsigned int d = 0; d < dim; ++d)
      point << (d == 0 ? "" : ", ") << (*first)[d + 1];
    AssertThrow(false,
                ExcMessage(
                  when +
                  ", the crack has left the PD-only zone before the region grew: a particle "
                  "the run damaged (damage index at least <Coupling/Adaptive region/"
                  "Damage threshold> = " +
                  ParameterUtilities::format_number(damage_threshold) +
                  " above the pre-cracks') at (" + point.str() +
                  ") m lies where beta = " + ParameterUtilities::format_number(least) +
                  " < 1, where the FE field bridges the crack; the run stops rather than arrest "
                  "or slow the crack there. The zone must lead the crack: lower <Coupling/"
                  "Adaptive region/Check interval> (now " +
                  std::to_string(interval) +
                  " steps), or raise <Coupling/Adaptive region/Damage distance> (now " +
                  ParameterUtilities::format_number(damage_distance) +
                  " m; it must exceed the distance the crack runs between two checks) with "
                  "<Core radius> (now " +
                  ParameterUtilities::format_number(core_radius) + " m)."));
  }

  template <int dim>
  void
  AdaptiveRegion<dim>::check_conditions_outside(const FERegion<dim>           &fe,
                                                const std::vector<Point<dim>> &new_seeds,
                                                const std::string             &when,
                                                const std::string             &section) const
  {
    // beta of the new seeds alone: a condition inside the file's own PD zone is the file's.
    const auto beta = [&](const Point<dim> &x) {
      double b = 0.;
      for (const auto &s : new_seeds)
        b = std::max(b, disk_blending(seed_distance(x, s)));
      return b;
    };
    // Per condition: a point of one of its faces where beta > 0 (this rank's first).
    const auto         &conditions = fe.conditions();
    std::vector<double> reached(conditions.size() * (dim + 1), 0.);
    for (const auto &cell : fe.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            for (unsigned int c = 0; c < conditions.size(); ++c)
              if (conditions[c].boundary_ids.count(face->boundary_id()) &&
                  reached[c * (dim + 1)] == 0.)
                for (const unsigned int v : face->vertex_indices())
                  if (beta(face->vertex(v)) > 0. && reached[c * (dim + 1)] == 0.)
                    {
                      reached[c * (dim + 1)] = 1.;
                      for (unsigned int d = 0; d < dim; ++d)
                        reached[c * (dim + 1) + 1 + d] = face->vertex(v)[d];
                    }
    const auto all = Utilities::MPI::all_gather(fe.get_triangulation().get_communicator(), reached);
    for (unsigned int c = 0; c < conditions.size(); ++c)
      for (const auto &part : all)
        if (part[c * (dim + 1)] != 0.)
          {
            Point<dim> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = part[c * (dim + 1) + 1 + d];
            std::ostringstream where;
            where << p;
            const std::string name =
              section.empty() ?
                conditions[c].name :
                section + "Finite elements/Boundary conditions/" + conditions[c].name;
            AssertThrow(false,
                        ExcMessage(when + ", the PD zone would reach the FE boundary condition <" +
                                   name + "> (beta > 0 at its boundary point " + where.str() +
                                   "), which acts on the FE field only. Nothing was converted; "
                                   "the run stops here. Move the condition away from the crack "
                                   "path, reduce <Coupling/Adaptive region/Core radius> or <Ramp "
                                   "width>, keep the seeds of the criterion 'principal strain' "
                                   "off it (<Coupling/Adaptive region/Strain region>), or give "
                                   "the particles that condition (<" +
                                   section +
                                   "Boundary conditions>) inside a PD zone of <Coupling/Blending "
                                   "function>."));
          }
  }

  template class AdaptiveRegion<2>;
  template class AdaptiveRegion<3>;
} // namespace perideal
