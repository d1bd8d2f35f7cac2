// ---------------------------------------------------------------------
// PeriDeal: how a quasi-static run advances its load (<Solver/Control>).
// ---------------------------------------------------------------------
#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/solvers/quasi_static_control.h>

namespace perideal
{
  using namespace dealii;

  void
  QuasiStaticControl::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.enter_subsection("Control");
    prm.declare_entry(
      "Method",
      "load steps",
      Patterns::Selection("load steps|sequentially linear"),
      "Quasi-static runs: 'load steps' applies <Solver/Load steps> equal increments of the load "
      "factor, with re-solves while bonds break; 'sequentially linear' (<Solver/Type> = static "
      "only) goes event by event: the linear solution under the conditions at <Time "
      "stepping/End time> is scaled so that the most critical intact bond just reaches the "
      "critical stretch, that bond breaks, and the next event is solved. The load factor may "
      "fall (snap-back), so unstable crack growth shows as a falling load. The run ends when the "
      "body separates (<Separation load fraction>), a free particle loses its last bond, the "
      "load factor would exceed 1, or after <Maximum events>.");
    prm.declare_entry(
      "Load history",
      "proportional",
      Patterns::Selection("proportional|time"),
      "Load steps: how the conditions follow the load factor lambda in [0, 1]. 'proportional': "
      "the displacements and loads of the condition functions at t = <Time stepping/End time>, "
      "times lambda (every load grows in proportion). 'time': the functions evaluated at t = "
      "lambda x End time, unscaled, so that any load path can be written as a function of t, "
      "e.g. a force applied and then held while a displacement grows. 'sequentially linear' "
      "accepts 'proportional' only.");
    prm.declare_entry("Load point",
                      "",
                      Patterns::Anything(),
                      "The name of a displacement condition (of <Boundary conditions/Names> or "
                      "<Finite elements/Boundary conditions/Names>): its reaction is the load and "
                      "its mean displacement the load-point displacement (statistics columns "
                      "load, load_point_displacement). Required by 'sequentially linear'; empty: "
                      "no load point.");
    prm.declare_entry("Load component",
                      "",
                      Patterns::Anything(),
                      "The component of the load and the load-point displacement, a name of the "
                      "problem's layout (x, y, z for displacements) that <Load point> prescribes.");
    prm.declare_entry("Event tolerance",
                      "1e-6",
                      Patterns::Double(),
                      "Sequentially linear: bonds whose critical load factor lies within (1 + "
                      "this) of the smallest break in the same event (bonds that symmetry makes "
                      "equally critical break together whatever the round-off); accepted: [0, "
                      "0.1].");
    prm.declare_entry("Separation load fraction",
                      "0.05",
                      Patterns::Double(),
                      "Sequentially linear: the body counts as separated, and the run ends, once "
                      "the load (the reaction of <Load point>) falls below this fraction of its "
                      "peak; accepted: (0, 1).");
    prm.declare_entry("Maximum events",
                      "100000",
                      Patterns::Integer(),
                      "Sequentially linear: the run ends after this many events (each one linear "
                      "solve); accepted: >= 1.");
    prm.declare_entry("Cut above broken bonds",
                      "0",
                      Patterns::Integer(),
                      "Load steps: a load step that breaks more bonds than this (or whose solve "
                      "does not converge) is undone and solved again with half the increment of "
                      "the load factor, up to <Maximum step cuts> times; after a step that breaks "
                      "at most half as many, the increment doubles again, up to 1/<Solver/Load "
                      "steps>. 0: steps are never cut. Accepted: >= 0.");
    prm.declare_entry("Maximum step cuts",
                      "10",
                      Patterns::Integer(),
                      "Load steps with <Cut above broken bonds> > 0: the largest number of "
                      "successive cuts of one step (the smallest increment is 1/<Solver/Load "
                      "steps> / 2^this); a step that still breaks too many bonds is then kept, "
                      "one that does not converge stops the run with its last iterate written. "
                      "Accepted: [0, 50].");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  void
  QuasiStaticControl::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.enter_subsection("Control");
    method     = prm.get("Method") == "sequentially linear" ? LoadControl::sequentially_linear :
                                                              LoadControl::load_steps;
    history    = prm.get("Load history") == "time" ? LoadHistory::time : LoadHistory::proportional;
    load_point = prm.get("Load point");
    load_component      = prm.get("Load component");
    event_tolerance     = prm.get_double("Event tolerance");
    separation_fraction = prm.get_double("Separation load fraction");
    const long events   = prm.get_integer("Maximum events");
    const long cut      = prm.get_integer("Cut above broken bonds");
    const long cuts     = prm.get_integer("Maximum step cuts");
    prm.leave_subsection();
    prm.leave_subsection();
    AssertThrow(event_tolerance >= 0. && event_tolerance <= 0.1,
                ExcMessage("The parameter <Solver/Control/Event tolerance> is " +
                           ParameterUtilities::format_number(event_tolerance) +
                           "; accepted: [0, 0.1] (a relative band of critical load factors)."));
    AssertThrow(separation_fraction > 0. && separation_fraction < 1.,
                ExcMessage("The parameter <Solver/Control/Separation load fraction> is " +
                           ParameterUtilities::format_number(separation_fraction) +
                           "; accepted: (0, 1) (a fraction of the peak load)."));
    AssertThrow(events >= 1,
                ExcMessage("The parameter <Solver/Control/Maximum events> is " +
                           std::to_string(events) + "; accepted: >= 1."));
    max_events = static_cast<unsigned int>(events);
    AssertThrow(cut >= 0,
                ExcMessage("The parameter <Solver/Control/Cut above broken bonds> is " +
                           std::to_string(cut) + "; accepted: >= 0 (0: never cut)."));
    AssertThrow(cuts >= 0 && cuts <= 50,
                ExcMessage("The parameter <Solver/Control/Maximum step cuts> is " +
                           std::to_string(cuts) + "; accepted: [0, 50]."));
    cut_threshold = static_cast<unsigned int>(cut);
    max_cuts      = static_cast<unsigned int>(cuts);
    AssertThrow(method != LoadControl::sequentially_linear || history == LoadHistory::proportional,
                ExcMessage("<Solver/Control/Method> = sequentially linear scales one linear "
                           "solution, so it needs <Solver/Control/Load history> = proportional "
                           "(given: time); for a load path of t use <Method> = load steps."));
    AssertThrow(method != LoadControl::sequentially_linear || !load_point.empty(),
                ExcMessage("<Solver/Control/Method> = sequentially linear needs a <Solver/Control/"
                           "Load point>: the displacement condition whose load decides when the "
                           "body has separated."));
  }
} // namespace perideal
