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
   * 1333, 1223, 2223, 2333, 1123 (the note's parity blocks).
   */
  namespace anisotropic_micromodulus
  {
    /// The 15 independent components of a completely symmetric 4th-order tensor in 3D.
    using Components = std::array<double, 15>;

    /**
     * @brief The exponents (a, b, c) of component @p k: the index multiset 1^a 2^b 3^c.
     */
    std::array<unsigned int, 3>
    component_exponents(const unsigned int k);

    /**
     * @brief The name of component @p k, e.g. "1123".
     */
    std::string
    component_name(const unsigned int k);

    /**
     * @brief The completely symmetric part of @p C: each component the mean of the entries of
     * C over the orderings of its index multiset, (1/24) sum over permutations.
     */
    Components
    completely_symmetric_part(const dealii::SymmetricTensor<4, 3> &C);

    /**
     * @brief The tensor of the completely symmetric components @p values.
     */
    dealii::SymmetricTensor<4, 3>
    to_tensor(const Components &values);

    /**
     * @brief One of the six Cauchy relations (seed note 004, sec. 1.1) in Voigt notation, e.g.
     * "C66 = C12", and the difference of its sides.
     */
    struct CauchyRelation
    {
      std::string relation;
      double      difference;
    };

    /**
     * @brief The six Cauchy relations C66 = C12, C44 = C23, C55 = C13, C56 = C14, C46 = C25,
     * C45 = C36 of @p C (they hold iff C is completely symmetric) with their differences.
     */
    std::vector<CauchyRelation>
    cauchy_relations(const dealii::SymmetricTensor<4, 3> &C);

    /**
     * @brief The directional modulus c(n) = Lambda_ijkl n_i n_j n_k n_l of the unit vector @p n.
     */
    double
    directional_modulus(const Components &Lambda, const dealii::Tensor<1, 3> &n);

    /**
     * @brief The mean of c(n) over the unit sphere, Lambda_iijj / 5.
     */
    double
    mean_directional_modulus(const Components &Lambda);

    /**
     * @brief The bonds of one interior particle of a lattice: relative positions xi and
     * weights beta V_j (partial-volume factor times neighbour volume).
     */
    struct LatticeFamily
    {
      std::vector<dealii::Tensor<1, 3>> xi;
      std::vector<double>               weight;
    };

    /**
     * @brief The family of the particle with the most bonds over all ranks (an interior
     * particle; the first on the lowest rank that owns one), the same on every rank
     * (collective).
     */
    LatticeFamily
    interior_family(const ParticleSystem<3> &particles);

    /**
     * @brief The matrix M of C = M Lambda for the micromodulus lambda(xi) = c(n)/|xi|^3
     * (omega = 1/|xi|) summed over @p family: C_ijkl = 1/2 sum_b lambda_b xi_i xi_j xi_k xi_l
     * w_b, i.e. M_(alpha, beta) = 1/2 sum_b w_b |xi_b| mult(beta) n_b^(alpha + beta).
     */
    dealii::FullMatrix<double>
    lattice_moment_matrix(const LatticeFamily &family);

    /**
     * @brief The continuum M over the ball of radius @p horizon: M_(alpha, beta) = delta^4/8
     * mult(beta) int_S n^(alpha + beta) dS (exact sphere moments); its inverse is the note's
     * closed form Lambda = (2/m)[315/8 C - 105/4 sym(I x tr C) + 15/8 trtr C sym(I x I)],
     * m = pi delta^4.
     */
    dealii::FullMatrix<double>
    continuum_moment_matrix(const double horizon);

    /**
     * @brief The Lambda with M Lambda = @p C.
     */
    Components
    solve(const dealii::FullMatrix<double> &M, const Components &C);

    /**
     * @brief M Lambda.
     */
    Components
    multiply(const dealii::FullMatrix<double> &M, const Components &Lambda);

    /**
     * @brief The Frobenius norm of the tensor of @p values (each component times its number
     * of orderings).
     */
    double
    norm(const Components &values);

    /**
     * @brief Where c(n) is negative on the unit sphere (a 1 degree grid in polar angle and
     * azimuth): the area fraction, the smallest value and its direction.
     */
    struct DirectionScan
    {
      double               negative_fraction = 0.;
      double               minimum           = 0.;
      dealii::Tensor<1, 3> minimum_direction;
    };

    /**
     * @brief The DirectionScan of @p Lambda.
     */
    DirectionScan
    scan_directions(const Components &Lambda);

    /**
     * @brief The Fourier symbol K(k) = sum_b c(n_b) w_b/|xi_b| n_b n_b^T (1 - cos k.xi_b) of the
     * interior operator of @p family (-K(k) u is the force density of u e^(i k.x)), on a grid
     * of @p n_k^3 wave vectors of the cell [0, 2 pi/spacing)^3 without k = 0: the smallest
     * eigenvalue over the grid relative to the largest, and the wave vector of the smallest.
     */
    struct SymbolScan
    {
      double               relative_minimum = 0.;
      dealii::Tensor<1, 3> wave_vector;
    };

    /**
     * @brief The SymbolScan of @p Lambda on @p family (lattice spacing @p spacing).
     */
    SymbolScan
    scan_symbol(const Components    &Lambda,
                const LatticeFamily &family,
                const double         spacing,
                const unsigned int   n_k);
  } // namespace anisotropic_micromodulus
} // namespace perideal

#endif
