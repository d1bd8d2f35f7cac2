// ---------------------------------------------------------------------
// PeriDeal: the failure law of a bond beyond its elastic limit (brittle, or linear softening
// in saw-tooth form for the sequentially linear control).
// ---------------------------------------------------------------------
#ifndef perideal_pd_bond_softening_h
#define perideal_pd_bond_softening_h

#include <string>

namespace perideal
{
  /**
   * @brief How a bond fails (<Material/critical stretch/Failure law>): brittle (it snaps at the
   * critical stretch s_G) or linear softening (BondSoftening).
   */
  enum class BondFailure
  {
    /// The bond breaks at s_G.
    brittle,
    /// The bond softens linearly from s_G / sqrt(n) to s_G sqrt(n) (BondSoftening).
    linear_softening
  };

  /**
   * @brief Linear softening of a bond whose brittle counterpart breaks at the stretch s_G
   * (doc/theory/models.md, "Softening PMB bonds"), in the saw-tooth form of the sequentially
   * linear control (Rots, Belletti & Invernizzi 2008, Eng. Fract. Mech. 75:4, sec. 3).
   *
   * The envelope: the force k s up to the elastic limit s0, then falling linearly to zero at
   * the final stretch s1, F = k s0 (s1 - s) / (s1 - s0); unloading and reloading are secant
   * (irreversible). Its work to break, 1/2 k s0 s1 |xi|, equals the brittle bond's
   * 1/2 k s_G^2 |xi| when s0 s1 = s_G^2: with the ratio n = s1 / s0 > 1 (<Softening ratio>),
   * s0 = s_G / sqrt(n) and s1 = s_G sqrt(n). So the bond dissipates what the brittle bond does,
   * and the calibration of s_G to the fracture energy (continuum or lattice) carries over.
   *
   * The saw-tooth (N = <Softening teeth>): in units of s0, the stretches x_i = n^(i/N),
   * i = 0 ... N, on the envelope, whose secant factors are mu_i = (n / x_i - 1) / (n - 1)
   * (mu_0 = 1, mu_N = 0). Tooth i is the bond with the stiffness mu_i k; it drops to tooth i + 1
   * at the stretch x~_i = sqrt(x_i x_{i+1}) = n^((i + 1/2)/N), where the dissipated
   * 1/2 k (mu_i - mu_{i+1}) x~_i^2 s0^2 |xi| equals the envelope's exactly over [x_i, x_{i+1}]
   * (x^2 (-dmu/dx) = n / (n - 1) is constant along a linear softening branch): each tooth
   * dissipates 1/2 k s0^2 |xi| n (x_{i+1} - x_i) / (n - 1), together 1/2 k s0 s1 |xi|. Each
   * tooth's peak force mu_i k x~_i s0 is n^(1/(2N)) times the envelope's at the start x_i of its
   * secant: the largest force of the saw-tooth is n^(1/(2N)) k s0 (the strength's ripple).
   */
  class BondSoftening
  {
  public:
    /**
     * @brief Brittle: no softening (teeth() = 1, the drop at s_G).
     */
    BondSoftening() = default;

    /**
     * @brief Linear softening with @p ratio n = s1 / s0 > 1 and @p teeth N >= 1 teeth.
     */
    BondSoftening(const double ratio, const unsigned int teeth);

    /**
     * @brief The failure law: brittle or linear softening.
     */
    BondFailure
    law() const;

    /**
     * @brief The ratio n = s1 / s0 of the final stretch to the elastic limit (1 if brittle).
     */
    double
    ratio() const;

    /**
     * @brief The number N of teeth (1 if brittle).
     */
    unsigned int
    teeth() const;

    /**
     * @brief The elastic limit s0 = s_G / sqrt(n) for the brittle critical stretch @p s_G.
     */
    double
    elastic_limit(const double s_G) const;

    /**
     * @brief The force of the envelope over k s0 at the stretch @p x in units of s0: x up to
     * 1, then (n - x) / (n - 1) up to n, then 0.
     */
    double
    envelope(const double x) const;

    /**
     * @brief The secant factor mu_i of tooth @p i (0 <= i <= N; mu_0 = 1, mu_N = 0).
     */
    double
    secant_factor(const unsigned int i) const;

    /**
     * @brief The stretch x~_i, in units of s0, at which tooth @p i (i < N) drops to tooth
     * i + 1.
     */
    double
    drop_stretch(const unsigned int i) const;

    /**
     * @brief The stretch at which tooth @p i drops, over the brittle critical stretch s_G:
     * x~_i / sqrt(n) (1 if brittle). A bond of tooth i reaches its limit where its stretch
     * reaches s_G times this.
     */
    double
    drop_over_brittle(const unsigned int i) const;

    /**
     * @brief The energy tooth @p i dissipates when it drops, over 1/2 k s0^2 |xi|:
     * (mu_i - mu_{i+1}) x~_i^2 = n (x_{i+1} - x_i) / (n - 1).
     */
    double
    tooth_dissipation(const unsigned int i) const;

    /**
     * @brief A line for the log: "brittle" or the law with n, N and the elastic limit's
     * fraction of s_G.
     */
    std::string
    summary() const;

  private:
    BondFailure  failure = BondFailure::brittle;
    double       n       = 1.;
    unsigned int n_teeth = 1;
  };
} // namespace perideal

#endif
