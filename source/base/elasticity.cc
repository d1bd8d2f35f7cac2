// ---------------------------------------------------------------------
// PeriDeal: linear elasticity tensors (isotropic and anisotropic, 2D and 3D).
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/elasticity.h>
#include <perideal/base/parameter_utilities.h>

#include <array>
#include <cmath>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // Voigt index of the symmetric pair (i, j) in 3D: 11 22 33 23 13 12.
    unsigned int
    voigt_index(const unsigned int i, const unsigned int j)
    {
      static const unsigned int table[3][3] = {{0, 5, 4}, {5, 1, 3}, {4, 3, 2}};
      return table[i][j];
    }

    // The 6 x 6 stiffness of the orthotropic compliance given by engineering constants.
    FullMatrix<double>
    orthotropic_stiffness(const std::array<double, 3> &E,
                          const std::array<double, 3> &nu, // nu12, nu13, nu23
                          const std::array<double, 3> &G)  // G23, G13, G12 (Voigt order)
    {
      FullMatrix<double> compliance(6, 6);
      compliance(0, 0) = 1. / E[0];
      compliance(1, 1) = 1. / E[1];
      compliance(2, 2) = 1. / E[2];
      compliance(0, 1) = compliance(1, 0) = -nu[0] / E[0];
      compliance(0, 2) = compliance(2, 0) = -nu[1] / E[0];
      compliance(1, 2) = compliance(2, 1) = -nu[2] / E[1];
      for (unsigned int k = 0; k < 3; ++k)
        compliance(3 + k, 3 + k) = 1. / G[k];
      FullMatrix<double> stiffness(6, 6);
      stiffness.invert(compliance);
      return stiffness;
    }

    // The symmetry classes by their names in <Symmetry>.
    const ParameterUtilities::Choices<ElasticMaterial::Symmetry> &
    symmetries()
    {
      using Symmetry                                           = ElasticMaterial::Symmetry;
      static const ParameterUtilities::Choices<Symmetry> names = {
        {"isotropic", Symmetry::isotropic},
        {"cubic", Symmetry::cubic},
        {"transversely isotropic", Symmetry::transversely_isotropic},
        {"orthotropic", Symmetry::orthotropic},
        {"general", Symmetry::general}};
      return names;
    }
  } // namespace

  const ParameterUtilities::Choices<PlanarAssumption> &
  planar_assumption_names()
  {
    static const ParameterUtilities::Choices<PlanarAssumption> names = {
      {"plane stress", PlanarAssumption::plane_stress},
      {"plane strain", PlanarAssumption::plane_strain}};
    return names;
  }

  PlanarAssumption
  planar_assumption_from_name(const std::string &name, const int dim)
  {
    if (dim == 3)
      return PlanarAssumption::three_dimensional;
    return ParameterUtilities::choice(planar_assumption_names(),
                                      name,
                                      "Material/Planar assumption");
  }

  template <int dim>
  SymmetricTensor<4, dim>
  isotropic_elasticity_tensor(const double           youngs_modulus,
                              const double           poisson_ratio,
                              const PlanarAssumption planar)
  {
    const double mu = youngs_modulus / (2. * (1. + poisson_ratio));
    double       lambda =
      youngs_modulus * poisson_ratio / ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    if (planar == PlanarAssumption::plane_stress)
      lambda = 2. * lambda * mu / (lambda + 2. * mu);
    const auto identity = unit_symmetric_tensor<dim>();
    return lambda * outer_product(identity, identity) + 2. * mu * identity_tensor<dim>();
  }

  template <int dim>
  SymmetricTensor<4, dim>
  reduce_elasticity_tensor(const FullMatrix<double> &voigt, const PlanarAssumption planar)
  {
    Assert(voigt.m() == 6 && voigt.n() == 6, ExcDimensionMismatch(voigt.m(), 6));
    SymmetricTensor<4, dim> C;
    if (dim == 3)
      {
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int l = k; l < dim; ++l)
                C[i][j][k][l] = voigt(voigt_index(i, j), voigt_index(k, l));
        return C;
      }
    // In-plane Voigt components 11, 22, 12.
    const std::array<unsigned int, 3> in_plane = {{0, 1, 5}};
    FullMatrix<double>                block(3, 3);
    if (planar == PlanarAssumption::plane_strain)
      {
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            block(a, b) = voigt(in_plane[a], in_plane[b]);
      }
    else
      {
        AssertThrow(planar == PlanarAssumption::plane_stress,
                    ExcMessage("A 2D elasticity tensor needs plane stress or plane strain."));
        FullMatrix<double> compliance(6, 6), in_plane_compliance(3, 3);
        compliance.invert(voigt);
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            in_plane_compliance(a, b) = compliance(in_plane[a], in_plane[b]);
        block.invert(in_plane_compliance);
      }
    const auto index2d = [](const unsigned int i, const unsigned int j) { return i == j ? i : 2u; };
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = k; l < dim; ++l)
            C[i][j][k][l] = block(index2d(i, j), index2d(k, l));
    return C;
  }

  FullMatrix<double>
  rotate_voigt_stiffness(const FullMatrix<double> &voigt, const Tensor<2, 3> &rotation)
  {
    // C'_ijkl = R_ia R_jb R_kc R_ld C_abcd on the full tensor; the Voigt matrix holds C_abcd.
    Tensor<4, 3> C, rotated;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int d = 0; d < 3; ++d)
            C[a][b][c][d] = voigt(voigt_index(a, b), voigt_index(c, d));
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
            {
              double sum = 0.;
              for (unsigned int a = 0; a < 3; ++a)
                for (unsigned int b = 0; b < 3; ++b)
                  for (unsigned int c = 0; c < 3; ++c)
                    for (unsigned int d = 0; d < 3; ++d)
                      sum += rotation[i][a] * rotation[j][b] * rotation[k][c] * rotation[l][d] *
                             C[a][b][c][d];
              rotated[i][j][k][l] = sum;
            }
    FullMatrix<double> result(6, 6);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = k; l < 3; ++l)
            result(voigt_index(i, j), voigt_index(k, l)) = rotated[i][j][k][l];
    return result;
  }

  Tensor<2, 3>
  rotation_from_euler_angles(const double phi, const double theta, const double psi)
  {
    const auto about = [](const unsigned int axis, const double degrees) {
      const double       c = std::cos(degrees * numbers::PI / 180.);
      const double       s = std::sin(degrees * numbers::PI / 180.);
      Tensor<2, 3>       R;
      const unsigned int p = (axis + 1) % 3, q = (axis + 2) % 3;
      R[axis][axis] = 1.;
      R[p][p]       = c;
      R[q][q]       = c;
      R[p][q]       = -s;
      R[q][p]       = s;
      return R;
    };
    // Intrinsic rotations: R = R_z(phi) R_x(theta) R_z(psi).
    return about(2, phi) * about(0, theta) * about(2, psi);
  }

  void
  ElasticMaterial::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Symmetry",
                      "isotropic",
                      Patterns::Selection(ParameterUtilities::selection(symmetries())),
                      "Symmetry class of the material; each class reads its own constants below "
                      "(material axes 1, 2, 3; the others are ignored).");
    prm.declare_entry("Young's modulus", "0", Patterns::Double(0.), "isotropic: E [Pa].");
    prm.declare_entry("Poisson's ratio",
                      "0",
                      Patterns::Double(-1., 0.5),
                      "isotropic: nu [-], in (-1, 1/2).");
    prm.declare_entry("Cubic constants",
                      "0, 0, 0",
                      Patterns::List(Patterns::Double(), 3, 3),
                      "cubic: C11, C12, C44 [Pa].");
    prm.declare_entry("Young's moduli",
                      "0, 0, 0",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "orthotropic: E1, E2, E3 [Pa]; transversely isotropic: E1, E3 [Pa].");
    prm.declare_entry("Poisson's ratios",
                      "0, 0, 0",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "orthotropic: nu12, nu13, nu23; transversely isotropic: nu12, nu13 "
                      "(nu_ij = -eps_j/eps_i under uniaxial stress along i).");
    prm.declare_entry("Shear moduli",
                      "0, 0, 0",
                      Patterns::List(Patterns::Double(), 1, 3),
                      "orthotropic: G12, G13, G23 [Pa]; transversely isotropic: G13 [Pa].");
    prm.declare_entry("Stiffness constants",
                      "",
                      Patterns::Anything(),
                      "general: the 21 constants C_IJ (I <= J) of the 6 x 6 Voigt stiffness "
                      "[Pa], Voigt order 11, 22, 33, 23, 13, 12, row by row.");
    prm.declare_entry("Orientation",
                      "0, 0, 0",
                      Patterns::List(Patterns::Double(), 3, 3),
                      "z-x-z Euler angles phi, theta, psi [degrees] of the material axes with "
                      "respect to the global axes. In 2D only phi keeps the plane a symmetry "
                      "plane of the material.");
    ThermalExpansion::declare_parameters(prm, true);
  }

  void
  ElasticMaterial::parse_parameters(ParameterHandler &prm, const std::string &section)
  {
    const auto numbers = [&](const std::string &entry) {
      std::vector<double> values;
      for (const auto &v : Utilities::split_string_list(prm.get(entry), ','))
        values.push_back(Utilities::string_to_double(v));
      return values;
    };
    const auto require_count =
      [&](const std::string &entry, const std::vector<double> &values, const std::size_t n) {
        AssertThrow(values.size() == n,
                    ExcMessage("The parameter <" + section + "/" + entry + "> needs " +
                               std::to_string(n) + " values for <" + section + "/Symmetry> = " +
                               ParameterUtilities::choice_name(symmetries(), symmetry) + "."));
      };
    symmetry = ParameterUtilities::choice(symmetries(), prm.get("Symmetry"), section + "/Symmetry");
    if (symmetry == Symmetry::isotropic)
      {
        E  = prm.get_double("Young's modulus");
        nu = prm.get_double("Poisson's ratio");
        ParameterUtilities::require_positive(E, section + "/Young's modulus");
        AssertThrow(nu > -1. && nu < 0.5,
                    ExcMessage("The parameter <" + section + "/Poisson's ratio> is " +
                               ParameterUtilities::format_number(nu) +
                               "; accepted: -1 < nu < 1/2."));
        const double G = E / (2. * (1. + nu));
        stiffness      = orthotropic_stiffness({{E, E, E}}, {{nu, nu, nu}}, {{G, G, G}});
      }
    else if (symmetry == Symmetry::cubic)
      {
        const auto c = numbers("Cubic constants");
        require_count("Cubic constants", c, 3);
        stiffness.reinit(6, 6);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            stiffness(i, j) = (i == j ? c[0] : c[1]);
        for (unsigned int i = 3; i < 6; ++i)
          stiffness(i, i) = c[2];
      }
    else if (symmetry == Symmetry::transversely_isotropic)
      {
        const auto e = numbers("Young's moduli"), n = numbers("Poisson's ratios"),
                   g = numbers("Shear moduli");
        require_count("Young's moduli", e, 2);
        require_count("Poisson's ratios", n, 2);
        require_count("Shear moduli", g, 1);
        const double G12 = e[0] / (2. * (1. + n[0]));
        stiffness =
          orthotropic_stiffness({{e[0], e[0], e[1]}}, {{n[0], n[1], n[1]}}, {{g[0], g[0], G12}});
      }
    else if (symmetry == Symmetry::orthotropic)
      {
        const auto e = numbers("Young's moduli"), n = numbers("Poisson's ratios"),
                   g = numbers("Shear moduli");
        require_count("Young's moduli", e, 3);
        require_count("Poisson's ratios", n, 3);
        require_count("Shear moduli", g, 3);
        stiffness =
          orthotropic_stiffness({{e[0], e[1], e[2]}}, {{n[0], n[1], n[2]}}, {{g[2], g[1], g[0]}});
      }
    else
      {
        const auto c = numbers("Stiffness constants");
        require_count("Stiffness constants", c, 21);
        stiffness.reinit(6, 6);
        unsigned int k = 0;
        for (unsigned int i = 0; i < 6; ++i)
          for (unsigned int j = i; j < 6; ++j, ++k)
            stiffness(i, j) = stiffness(j, i) = c[k];
      }

    // The stiffness must be positive definite (a stable material).
    {
      FullMatrix<double> test(stiffness);
      bool               positive = true;
      for (unsigned int k = 0; k < 6 && positive; ++k)
        {
          positive = test(k, k) > 0.;
          for (unsigned int i = k + 1; i < 6 && positive; ++i)
            {
              const double factor = test(i, k) / test(k, k);
              for (unsigned int j = k; j < 6; ++j)
                test(i, j) -= factor * test(k, j);
            }
        }
      AssertThrow(positive,
                  ExcMessage("The elastic constants in <" + section + "> (Symmetry = " +
                             ParameterUtilities::choice_name(symmetries(), symmetry) +
                             ") do not give a positive definite stiffness: the material would be "
                             "unstable. Check the moduli and Poisson's ratios."));
    }

    const auto angles = numbers("Orientation");
    rotation          = rotation_from_euler_angles(angles[0], angles[1], angles[2]);
    if (angles[0] != 0. || angles[1] != 0. || angles[2] != 0.)
      stiffness = rotate_voigt_stiffness(stiffness, rotation);
    expansion.parse_parameters(prm, section, true);
  }

  ElasticMaterial
  ElasticMaterial::rotated(const Tensor<2, 3> &extra) const
  {
    ElasticMaterial result = *this;
    result.rotation        = extra * rotation;
    result.stiffness       = rotate_voigt_stiffness(stiffness, extra);
    return result;
  }

  const Tensor<2, 3> &
  ElasticMaterial::axes() const
  {
    return rotation;
  }

  const FullMatrix<double> &
  ElasticMaterial::voigt_stiffness() const
  {
    return stiffness;
  }

  template <int dim>
  SymmetricTensor<4, dim>
  ElasticMaterial::tensor(const PlanarAssumption planar) const
  {
    return reduce_elasticity_tensor<dim>(stiffness, planar);
  }

  bool
  ElasticMaterial::is_isotropic() const
  {
    return symmetry == Symmetry::isotropic;
  }

  double
  ElasticMaterial::youngs_modulus() const
  {
    return E;
  }

  double
  ElasticMaterial::poisson_ratio() const
  {
    return nu;
  }

  SymmetricTensor<2, 3>
  ElasticMaterial::thermal_expansion() const
  {
    return expansion.tensor(rotation);
  }

  const ThermalExpansion &
  ElasticMaterial::thermal_expansion_entry() const
  {
    return expansion;
  }

  std::string
  ElasticMaterial::summary() const
  {
    std::ostringstream out;
    out << ParameterUtilities::choice_name(symmetries(), symmetry);
    if (is_isotropic())
      out << ", E = " << E << " Pa, nu = " << nu;
    else
      out << ", C11 = " << stiffness(0, 0) << " Pa, C22 = " << stiffness(1, 1)
          << " Pa, C66 = " << stiffness(5, 5) << " Pa (global axes)";
    if (!expansion.is_zero())
      out << ", " << expansion.summary();
    return out.str();
  }

  template SymmetricTensor<4, 2>
  isotropic_elasticity_tensor<2>(const double, const double, const PlanarAssumption);
  template SymmetricTensor<4, 3>
  isotropic_elasticity_tensor<3>(const double, const double, const PlanarAssumption);
  template SymmetricTensor<4, 2>
  reduce_elasticity_tensor<2>(const FullMatrix<double> &, const PlanarAssumption);
  template SymmetricTensor<4, 3>
  reduce_elasticity_tensor<3>(const FullMatrix<double> &, const PlanarAssumption);
  template SymmetricTensor<4, 2>
  ElasticMaterial::tensor<2>(const PlanarAssumption) const;
  template SymmetricTensor<4, 3>
  ElasticMaterial::tensor<3>(const PlanarAssumption) const;
} // namespace perideal
