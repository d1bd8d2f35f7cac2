// ---------------------------------------------------------------------
// PeriDeal: the micromodulus tensor of anisotropic linearized bond-based PD (seed 004).
// ---------------------------------------------------------------------
#ifndef perideal_pd_anisotropic_micromodulus_h
#define perideal_pd_anisotropic_micromodulus_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <perideal/pd/particle_system.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief The algebra of the anisotropic bond-based micromodulus (Trageser & Seleson,
   * SAND2019-12685C; seed note 004, sec. 1.3): completely symmetric 4th-order tensors in 3D
   * by their 15 independent components, the directional modulus c(n) = Lambda_ijkl n_i n_j n_k
   * n_l, the moment system C = M Lambda (continuum or the lattice's own neighbour sums), the
   * Cauchy relations and the stability checks of the set-up.
   *
   * Component k stands for the index multiset with exponents component_exponents(k) = (a, b,
   * c), a + b + c = 4, in the order 1111, 2222, 3333, 1122, 1133, 2233, 1112, 1222, 1233, 1113,
   * 1333, 1223, 2223, 2333, 1123 (the note's parity blocks). In 2D the 5 components 1111, 2222,
   * 1122, 1112, 1222 (the same order without the 3's; c = 0); the 2D moments carry the
   * thickness of the particle volumes.
   */
  namespace anisotropic_micromodulus
  {
    /// The number of independent components of a completely symmetric 4th-order tensor.
    template <int dim>
    constexpr std::size_t n_components = dim == 2 ? 5 : 15;

    /// The independent components of a completely symmetric 4th-order tensor in @p dim.
    template <int dim>
    using ComponentsOf = std::array<double, n_components<dim>>;

    /// The 15 independent components of a completely symmetric 4th-order tensor in 3D.
    using Components = ComponentsOf<3>;

    /**
     * @brief The exponents (a, b, c) of component @p k: the index multiset 1^a 2^b 3^c (c = 0
     * in 2D).
     */
    template <int dim = 3>
    std::array<unsigned int, 3>
    component_exponents(const unsigned int k);

    /**
     * @brief The name of component @p k, e.g. "1123".
     */
    template <int dim = 3>
    std::string
    component_name(const unsigned int k);

    /**
     * @brief The completely symmetric part of @p C: each component the mean of the entries of
     * C over the orderings of its index multiset, (1/24) sum over permutations.
     */
    template <int dim>
    ComponentsOf<dim>
    completely_symmetric_part(const dealii::SymmetricTensor<4, dim> &C);

    /**
     * @brief The tensor of the completely symmetric components @p values.
     */
    template <int dim = 3>
    dealii::SymmetricTensor<4, dim>
    to_tensor(const ComponentsOf<dim> &values);

    /**
     * @brief One of the six Cauchy relations (seed note 004, sec. 1.1) in Voigt notation, e.g.
     * "C66 = C12", and the difference of its sides.
     */
    struct CauchyRelation
    {
      /// The relation and the difference of its sides.
      ///@{
      std::string relation;
      double      difference;
      ///@}
    };

    /**
     * @brief The six Cauchy relations C66 = C12, C44 = C23, C55 = C13, C56 = C14, C46 = C25,
     * C45 = C36 of @p C (they hold iff C is completely symmetric) with their differences; in
     * 2D the one relation C66 = C12 (C_1212 = C_1122).
     */
    template <int dim>
    std::vector<CauchyRelation>
    cauchy_relations(const dealii::SymmetricTensor<4, dim> &C);

    /// The largest |C_ijkl| of @p C.
    template <int dim>
    double
    largest_component(const dealii::SymmetricTensor<4, dim> &C);

    /**
     * @brief The relations of cauchy_relations() that @p C violates by more than 1e-8 of its
     * largest component, for an error message: " <relation> is off by <difference> Pa (<the
     * difference over the largest component> of the largest constant);" each, empty if @p C
     * satisfies them all.
     */
    template <int dim>
    std::string
    cauchy_violations(const dealii::SymmetricTensor<4, dim> &C);

    /**
     * @brief The directional modulus c(n) = Lambda_ijkl n_i n_j n_k n_l of the unit vector @p n.
     */
    template <int dim>
    double
    directional_modulus(const ComponentsOf<dim> &Lambda, const dealii::Tensor<1, dim> &n);

    /**
     * @brief The mean of c(n) over the unit sphere, Lambda_iijj / 5 (over the unit circle in
     * 2D: 3 Lambda_iijj / 8).
     */
    template <int dim = 3>
    double
    mean_directional_modulus(const ComponentsOf<dim> &Lambda);

    /**
     * @brief The bonds of one interior particle of a lattice: relative positions xi and
     * weights chi V_j (partial-volume factor times neighbour volume).
     */
    template <int dim>
    struct Family
    {
      /// The bond vectors xi [m] and their weights beta V_j [m^3].
      ///@{
      std::vector<dealii::Tensor<1, dim>> xi;
      std::vector<double>                 weight;
      ///@}
    };

    /// The 3D family.
    using LatticeFamily = Family<3>;

    /**
     * @brief The family of an interior particle of the regular lattice
     * (ParticleSystem::lattice_family()): with a perturbed lattice, the calibration's reference.
     */
    template <int dim>
    Family<dim>
    interior_family(const ParticleSystem<dim> &particles);

    /**
     * @brief The matrix M of C = M Lambda for the micromodulus lambda(xi) = c(n)/|xi|^3
     * (omega = 1/|xi|) summed over @p family: C_ijkl = 1/2 sum_b lambda_b xi_i xi_j xi_k xi_l
     * w_b, i.e. M_(alpha, beta) = 1/2 sum_b w_b |xi_b| mult(beta) n_b^(alpha + beta).
     */
    template <int dim>
    dealii::FullMatrix<double>
    lattice_moment_matrix(const Family<dim> &family);

    /**
     * @brief The continuum M over the ball of radius @p horizon: M_(alpha, beta) = delta^4/8
     * mult(beta) int_S n^(alpha + beta) dS (exact sphere moments); its inverse is the note's
     * closed form Lambda = (2/m)[315/8 C - 105/4 sym(I x tr C) + 15/8 trtr C sym(I x I)],
     * m = pi delta^4. In 2D over the disc times the @p thickness h of the particle volumes:
     * M_(alpha, beta) = h delta^3/6 mult(beta) int_0^(2 pi) n^(alpha + beta) d theta.
     */
    template <int dim = 3>
    dealii::FullMatrix<double>
    continuum_moment_matrix(const double horizon, const double thickness = 1.);

    /**
     * @brief The Lambda with M Lambda = @p C.
     */
    template <std::size_t N>
    std::array<double, N>
    solve(const dealii::FullMatrix<double> &M, const std::array<double, N> &C);

    /**
     * @brief M Lambda.
     */
    template <std::size_t N>
    std::array<double, N>
    multiply(const dealii::FullMatrix<double> &M, const std::array<double, N> &Lambda);

    /**
     * @brief The Frobenius norm of the tensor of @p values (each component times its number
     * of orderings).
     */
    template <std::size_t N>
    double
    norm(const std::array<double, N> &values);

    /**
     * @brief Where c(n) is negative on the unit sphere (a 1 degree grid in polar angle and
     * azimuth; in 2D a 0.1 degree grid of the circle): the area (arc) fraction, the smallest
     * value and its direction.
     */
    template <int dim>
    struct DirectionScanOf
    {
      /// The fraction where c(n) < 0, the smallest c(n) and its direction n.
      ///@{
      double                 negative_fraction = 0.;
      double                 minimum           = 0.;
      dealii::Tensor<1, dim> minimum_direction;
      ///@}
    };

    /// The 3D scan.
    using DirectionScan = DirectionScanOf<3>;

    /**
     * @brief The DirectionScan of @p Lambda.
     */
    template <int dim = 3>
    DirectionScanOf<dim>
    scan_directions(const ComponentsOf<dim> &Lambda);

    /**
     * @brief The Fourier symbol K(k) = sum_b c(n_b) w_b/|xi_b| n_b n_b^T (1 - cos k.xi_b) of the
     * interior operator of @p family (-K(k) u is the force density of u e^(i k.x)), on a grid
     * of @p n_k^dim wave vectors of the cell [0, 2 pi/spacing)^dim without k = 0: the smallest
     * eigenvalue over the grid relative to the largest, and the wave vector of the smallest.
     */
    template <int dim>
    struct SymbolScanOf
    {
      /// The smallest eigenvalue relative to the largest, and its wave vector [1/m].
      ///@{
      double                 relative_minimum = 0.;
      dealii::Tensor<1, dim> wave_vector;
      ///@}
    };

    /// The 3D scan.
    using SymbolScan = SymbolScanOf<3>;

    /**
     * @brief A term a model adds to the symbol K(k) of the bond sum at the wave vector k (the
     * first argument), e.g. the plane-stress model's -s s^T / B
     * (AnisotropicPlaneStress::initialize()).
     */
    template <int dim>
    using SymbolTerm =
      std::function<void(const dealii::Tensor<1, dim> &, dealii::SymmetricTensor<2, dim> &)>;

    /**
     * @brief The SymbolScan of @p Lambda on @p family (lattice spacing @p spacing), with
     * @p extra_term added to K(k) at every wave vector if it is given.
     */
    template <int dim>
    SymbolScanOf<dim>
    scan_symbol(const ComponentsOf<dim> &Lambda,
                const Family<dim>       &family,
                const double             spacing,
                const unsigned int       n_k,
                const SymbolTerm<dim>   &extra_term = {});
  } // namespace anisotropic_micromodulus
} // namespace perideal

#endif
