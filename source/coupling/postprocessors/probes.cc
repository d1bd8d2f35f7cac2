// ---------------------------------------------------------------------
// PeriDeal: the displacement of the particles nearest to given points.
// ---------------------------------------------------------------------
#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/postprocessors/probes.h>

#include <algorithm>
#include <array>
#include <iomanip>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  Probes<dim>::initialize(const CoupledState<dim> &state)
  {
    // Per probe and rank: the distance to the nearest owned particle, then its coordinates.
    const auto               &points   = state.settings().probe_points;
    const unsigned int        n_probes = points.size(), width = dim + 1;
    const auto               &ps = state.pd().particles();
    const auto               &x  = ps.positions();
    std::vector<double>       nearest(n_probes * width, std::numeric_limits<double>::max());
    std::vector<unsigned int> nearest_index(n_probes, numbers::invalid_unsigned_int);
    for (unsigned int p = 0; p < n_probes; ++p)
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        {
          std::array<double, dim + 1> candidate;
          candidate[0] = x[i].distance(points[p]);
          for (unsigned int d = 0; d < dim; ++d)
            candidate[d + 1] = x[i][d];
          if (std::lexicographical_compare(candidate.begin(),
                                           candidate.end(),
                                           nearest.begin() + p * width,
                                           nearest.begin() + (p + 1) * width))
            {
              std::copy(candidate.begin(), candidate.end(), nearest.begin() + p * width);
              nearest_index[p] = i;
            }
        }
    const auto all = Utilities::MPI::all_gather(state.comm(), nearest);
    const auto me  = Utilities::MPI::this_mpi_process(state.comm());

    const double spacing = state.pd().discretization().spacing;
    probe_particles.resize(n_probes);
    probe_local_index.assign(n_probes, numbers::invalid_unsigned_int);
    for (unsigned int p = 0; p < n_probes; ++p)
      {
        unsigned int best = 0;
        for (unsigned int r = 1; r < all.size(); ++r)
          if (std::lexicographical_compare(all[r].begin() + p * width,
                                           all[r].begin() + (p + 1) * width,
                                           all[best].begin() + p * width,
                                           all[best].begin() + (p + 1) * width))
            best = r;
        const double       distance = all[best][p * width];
        std::ostringstream point;
        point << points[p];
        AssertThrow(distance <= spacing,
                    ExcMessage(
                      "<Output/Probe points>: the point (" + point.str() +
                      ") has no particle within one lattice spacing (" +
                      ParameterUtilities::format_number(spacing) + " m); the nearest is " +
                      ParameterUtilities::format_number(distance) +
                      " m away. Put each probe on the particles of <Discretization/Body> (coupled "
                      "runs: the PD region and its overlap)."));
        for (unsigned int d = 0; d < dim; ++d)
          probe_particles[p][d] = all[best][p * width + d + 1];
        if (best == me)
          probe_local_index[p] = nearest_index[p];
      }
  }

  template <int dim>
  void
  Probes<dim>::execute(const CoupledState<dim> &state,
                       const StepData          &data,
                       StatisticsFile          &statistics)
  {
    if (!(data.final_row || data.write_statistics) || probe_particles.empty())
      return;
    const auto         &points = state.settings().probe_points;
    const unsigned int  nc     = state.n_components();
    std::vector<double> values(points.size() * nc, 0.);
    for (unsigned int p = 0; p < points.size(); ++p)
      if (probe_local_index[p] != numbers::invalid_unsigned_int)
        for (unsigned int c = 0; c < nc; ++c)
          values[p * nc + c] = state.u.local_element(probe_local_index[p] * nc + c);
    Utilities::MPI::sum(values, state.comm(), values);
    const FieldLayout &layout = state.layout();
    // Every statistics row: the values in SI units (m, rad, K).
    if (data.write_statistics)
      for (unsigned int p = 0; p < points.size(); ++p)
        for (unsigned int c = 0; c < nc; ++c)
          statistics.add_value("probe" + std::to_string(p + 1) + "_" + layout.name(c),
                               values[p * nc + c]);
    if (!data.final_row || !state.is_root())
      return;
    // The summary: translations and scalars in micrometres, rotations in microradians, a
    // temperature in kelvin.
    const bool        temperature = layout.n_components(ComponentKind::temperature) == nc;
    const std::string label       = temperature ? "temperature [K]" :
                                    layout.n_components(ComponentKind::translation) == nc ?
                                                  "displacement [um]" :
                                                  "field (" + layout.names() + ") [um, urad]";
    const double      scale       = temperature ? 1. : 1e6;
    std::ostream     &log         = state.log();
    const auto        flags       = log.flags();
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        log << std::defaultfloat << "Probe " << p + 1 << " (" << points[p] << "): particle at ("
            << probe_particles[p] << "), " << label << ":" << std::scientific
            << std::setprecision(6);
        for (unsigned int c = 0; c < nc; ++c)
          log << ' ' << scale * values[p * nc + c];
        log << '\n';
      }
    log << std::flush;
    log.flags(flags);
  }

  template class Probes<2>;
  template class Probes<3>;
} // namespace perideal

PERIDEAL_REGISTER_POSTPROCESSOR(perideal::Probes,
                                "probes",
                                "the field at <Output/Probe points>: columns probe<k>_<component>.")
