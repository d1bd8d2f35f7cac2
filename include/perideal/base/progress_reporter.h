#ifndef perideal_base_progress_reporter_h
#define perideal_base_progress_reporter_h

#include <deal.II/base/mpi.h>

#include <chrono>
#include <ostream>

namespace perideal
{
  /**
   * Prints a one-line progress report of a time-stepping loop on rank 0, e.g.
   * @code
   * step 1200/5000  t = 1.234e-05 s  24%  elapsed 3.1 s  ETA 9.8 s
   * @endcode
   * at most once per @p interval seconds of wall time, and always at the last
   * step. The fraction done is step/n_steps (time/end_time if n_steps is 0);
   * the ETA extrapolates the wall time per step measured since the first
   * update(). Wall-clock output is meant for the console, never for test
   * output.
   */
  class ProgressReporter
  {
  public:
    /**
     * @brief Set up the reporter; the elapsed time counts from here.
     *
     * @param comm Communicator; only its rank 0 prints.
     * @param out Stream to print to (typically std::cout).
     * @param n_steps Total number of time steps.
     * @param end_time Simulated end time.
     * @param enabled If false, update() prints nothing.
     * @param interval Minimal wall time in seconds between two reports.
     */
    ProgressReporter(MPI_Comm           comm,
                     std::ostream      &out,
                     const unsigned int n_steps,
                     const double       end_time,
                     const bool         enabled,
                     const double       interval = 2.0);

    /**
     * @brief Report that step @p step (reaching simulated time @p time) is
     * done; prints if the interval has passed or if this is the last step.
     */
    void
    update(const unsigned int step, const double time);

  private:
    using Clock = std::chrono::steady_clock;

    /**
     * @brief Print the report line for @p step at wall time @p now.
     */
    void
    print(const unsigned int step, const double time, const Clock::time_point now);

    std::ostream      &out;
    const unsigned int n_steps;
    const double       end_time;
    const bool         active;
    const double       interval;

    Clock::time_point start;
    Clock::time_point last_report;

    /**
     * Wall time and step of the first update(), the base of the ETA.
     */
    bool              have_first_update;
    Clock::time_point first_update;
    unsigned int      first_step;
  };
} // namespace perideal

#endif
