// ---------------------------------------------------------------------
// PeriDeal: quasi-static fracture event by event (sequentially linear control).
// ---------------------------------------------------------------------
#ifndef perideal_coupling_solvers_sequentially_linear_h
#define perideal_coupling_solvers_sequentially_linear_h

#include <perideal/coupling/fracture_measures.h>
#include <perideal/coupling/solvers/load_stepping.h>
#include <perideal/coupling/solvers/quasi_static_control.h>

#include <vector>

namespace perideal
{
  /**
   * @brief <Solver/Control/Method> = sequentially linear (with <Solver/Type> = static): quasi-
   * static brittle fracture event by event, through snap-back, to separation.
   *
   * Each event solves the linearized equilibrium (CouplingMethod::solve_equilibrium()) under the
   * conditions at <Time stepping/End time> (load factor 1) with the bonds broken so far. Its
   * solution is linear in the load factor lambda, and so is the linearized stretch
   * s_b = xi . eta / |xi|^2 of every bond: the intact bond of the smallest critical factor
   * lambda_b = s0 / s_b (s_b > 0) reaches the critical stretch s0 first. The state is scaled to
   * lambda* = min lambda_b (the statistics row of the event: load factor, load, load-point
   * displacement, broken bonds, crack length), then the bonds with lambda_b <= lambda* (1 +
   * <Event tolerance>) break (their energy is dissipated; softening bonds, <Material/critical
   * stretch/Failure law> = linear softening, drop by a saw tooth instead, breaking at the last:
   * MaterialModel::limit_reached()) and the next event is solved. No
   * iteration, no load increment to choose: lambda* falls when the crack grows unstably
   * (snap-back), which a load- or displacement-controlled step cannot follow (Rots et al. 2008,
   * Eng. Fract. Mech. 75:4; doc/theory/fracture_control.md).
   *
   * The run ends, with the fields and the summary of its last event written, when the load (the
   * reaction of <Solver/Control/Load point>) falls below <Separation load fraction> of its peak
   * (separation), when no intact bond is stretched, when breaking the critical bonds would leave
   * a free particle without a bond (a loose piece: the next system would be singular), when
   * lambda* would exceed 1 (the state at load factor 1 is the last row) or after <Maximum
   * events>; the log says which. A solve that does not converge stops the run with its last
   * iterate written (LoadStepping::write_last_iterate()).
   *
   * Checkpoints every <Output/Checkpoint interval> events hold the state after the event's
   * bonds have broken and the peak so far (load, load factor and event: a part of the
   * checkpoint, Checkpoint::add_part()); --restart continues with the next event, bit for bit
   * on the same number of ranks.
   *
   * Refused before any work: another <Solver/Type>, a model whose bonds do not break by the
   * stretch of a displacement field (only 'bond based' and 'linear peridynamic solid'), no
   * damage model, <Output/Checkpoint time interval> (an event's load factor is no time: it
   * falls when a crack snaps back).
   */
  template <int dim>
  class SequentiallyLinear : public LoadStepping<dim>
  {
  public:
    /// The control of @p control (its method is sequentially_linear).
    explicit SequentiallyLinear(const QuasiStaticControl &control);

    void
    check(const CoupledState<dim> &state) const override;

    void
    setup(CoupledState<dim> &state) override;

    void
    run(CoupledState<dim>   &state,
        Postprocessors<dim> &postprocessors,
        Checkpoint<dim>     &checkpoint) override;

  private:
    /**
     * @brief The critical load factor lambda_b of every locally stored bond at the solution
     * (U, u) of load factor 1 (infinite for broken, unbreakable and compressed bonds) into
     * bond_factor; returns the smallest over all ranks. Collective.
     */
    double
    critical_factors(const CoupledState<dim> &state);

    /**
     * @brief The number of free particles (all ranks) that would keep no intact bond if the
     * bonds with lambda_b <= @p limit broke. Collective.
     */
    unsigned long
    loose_particles(const CoupledState<dim> &state, const double limit);

    /// The bonds with lambda_b <= @p limit reach their limit (MaterialModel::limit_reached():
    /// they break, listed for their released energy, or soften by a tooth).
    void
    break_bonds(CoupledState<dim> &state, const double limit) const;

    FractureMeasures<dim> measures;
    /// lambda_b of each locally stored bond.
    std::vector<double> bond_factor;
    /// Intact bonds per owned particle (loose_particles()).
    std::vector<unsigned int> intact_bonds;
  };
} // namespace perideal

#endif
