#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/progress_reporter.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace perideal
{
  ProgressReporter::ProgressReporter(MPI_Comm           comm,
                                     std::ostream      &out,
                                     const unsigned int n_steps,
                                     const double       end_time,
                                     const bool         enabled,
                                     const double       interval)
    : out(out)
    , n_steps(n_steps)
    , end_time(end_time)
    , active(enabled && dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    , interval(interval)
    , start(Clock::now())
    , last_report(start)
    , have_first_update(false)
    , first_step(0)
  {
    AssertThrow(interval >= 0.,
                dealii::ExcMessage("The progress report interval must be "
                                   "non-negative."));
  }



  void
  ProgressReporter::update(const unsigned int step, const double time)
  {
    if (!active)
      return;

    const Clock::time_point now = Clock::now();
    if (!have_first_update)
      {
        have_first_update = true;
        first_update      = now;
        first_step        = step;
      }

    const bool last_step = (n_steps > 0) ? (step >= n_steps) : (end_time > 0. && time >= end_time);
    const double since_last = std::chrono::duration<double>(now - last_report).count();
    if (last_step || since_last >= interval)
      {
        print(step, time, now);
        last_report = now;
      }
  }



  void
  ProgressReporter::print(const unsigned int step, const double time, const Clock::time_point now)
  {
    double fraction = 0.;
    if (n_steps > 0)
      fraction = static_cast<double>(step) / n_steps;
    else if (end_time > 0.)
      fraction = time / end_time;
    fraction = std::clamp(fraction, 0., 1.);

    const double elapsed = std::chrono::duration<double>(now - start).count();

    // Wall time per step since the first update, extrapolated to the end.
    double eta = -1.;
    if (n_steps > 0 && step > first_step)
      {
        const double per_step =
          std::chrono::duration<double>(now - first_update).count() / (step - first_step);
        eta = per_step * (n_steps > step ? n_steps - step : 0);
      }
    else if (fraction > 0.)
      eta = elapsed * (1. - fraction) / fraction;

    std::ostringstream line;
    line << "step " << step;
    if (n_steps > 0)
      line << '/' << n_steps;
    line << "  t = " << std::scientific << std::setprecision(3) << time << " s  "
         << static_cast<unsigned int>(std::floor(100. * fraction)) << "%  elapsed " << std::fixed
         << std::setprecision(1) << elapsed << " s  ETA ";
    if (eta >= 0.)
      line << eta << " s";
    else
      line << "-";
    out << line.str() << std::endl;
  }
} // namespace perideal
