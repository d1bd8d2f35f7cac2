// ---------------------------------------------------------------------
// The transfer operator P (FE shape functions at particle positions): particles over the right
// part of a plate whose FE weight 1 - beta vanishes for x >= 0.06 (FE_Nothing cells there).
// Checked, in 2D (Q1, Q2) and 3D (Q1), on 1 and 2 ranks:
// - the particles in FE-carrying cells are slaved, the others free (counted against the
//   geometry);
// - P U reproduces a linear displacement field exactly at the slaved particles;
// - P^T transfers forces and moments exactly: sum_a F_a = sum_i f_i and
//   sum_a x_a x F_a = sum_i x_i x f_i (linear completeness of the shape functions);
// - particles with rotations (a micropolar layout: x, y, rz; x, y, z, rx, ry, rz) coupled to
//   FE translations: the rotations of the slaved particles are 1/2 curl U (exact for the
//   linear field), and P^T turns their moments into nodal forces with no net force and the
//   same moment: sum_a x_a x F_a = sum_i (x_i x f_i + m_i);
// - layouts that do not match (a scalar field against FE translations) are refused;
// - a particle outside the mesh is refused.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/numerics/vector_tools.h>

#include <perideal/coupling/transfer_operator.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include <tests.h>

using namespace dealii;

namespace
{
  template <int dim>
  class LinearField : public Function<dim>
  {
  public:
    LinearField()
      : Function<dim>(dim)
    {}
    double
    value(const Point<dim> &x, const unsigned int c) const override
    {
      double v = 1e-4 * (c + 1);
      for (unsigned int d = 0; d < dim; ++d)
        v += 1e-3 * (1. + c + 2. * d) * x[d];
      return v;
    }
  };

  /// 1/2 curl of LinearField, about the axis @p r (0, 1, 2).
  template <int dim>
  double
  linear_field_rotation(const unsigned int r)
  {
    // du_k/dx_j = 1e-3 (1 + k + 2 j); theta_r = 1/2 (du_{r+2}/dx_{r+1} - du_{r+1}/dx_{r+2}).
    const unsigned int j = (r + 1) % 3, k = (r + 2) % 3;
    return 0.5e-3 * ((1. + k + 2. * j) - (1. + j + 2. * k));
  }

  /// The moment about the origin of the force @p f at @p x, as a vector of 3 components.
  template <int dim>
  Tensor<1, 3>
  moment_of(const Point<dim> &x, const Tensor<1, dim> &f)
  {
    Tensor<1, 3> x3, f3;
    for (unsigned int d = 0; d < dim; ++d)
      {
        x3[d] = x[d];
        f3[d] = f[d];
      }
    return cross_product_3d(x3, f3);
  }

  template <int dim>
  std::string
  generator_arguments()
  {
    return dim == 2 ? "8, 4 : 0, 0 : 0.1, 0.05 : false" :
                      "8, 4, 2 : 0, 0, 0 : 0.1, 0.05, 0.025 : false";
  }

  template <int dim>
  void
  make_fe(perideal::FERegion<dim> &fe, const unsigned int degree)
  {
    ParameterHandler prm;
    perideal::FERegion<dim>::declare_parameters(prm, {});
    prm.parse_input_from_string("subsection Finite elements\n"
                                "  set Generator = subdivided_hyper_rectangle\n"
                                "  set Generator arguments = " +
                                generator_arguments<dim>() +
                                "\n"
                                "  set Polynomial degree = " +
                                std::to_string(degree) +
                                "\n"
                                "  subsection Elasticity\n"
                                "    set Young's modulus = 1e9\n"
                                "    set Poisson's ratio = 0.25\n"
                                "  end\n"
                                "end\n");
    fe.parse_parameters(prm, perideal::PlanarAssumption::plane_stress, 1.);
    // beta ramps from 0 at x = 0.04 to 1 at x = 0.06.
    fe.setup(
      [](const Point<dim> &x) { return 1. - std::min(1., std::max(0., (x[0] - 0.04) / 0.02)); });
  }

  /// Particles of spacing 2.5 mm over [@p x_low, @p x_high] x [0, 0.05] (x [0, 0.025]).
  template <int dim>
  void
  generate_particles(perideal::ParticleSystem<dim> &particles,
                     const double                   x_low,
                     const double                   x_high)
  {
    typename perideal::ParticleSystem<dim>::Settings settings;
    settings.spacing = 0.0025;
    settings.horizon = 3.015 * settings.spacing;
    Point<dim> lower, upper;
    lower[0] = x_low;
    upper[0] = x_high;
    upper[1] = 0.05;
    if (dim == 3)
      upper[dim - 1] = 0.025;
    particles.generate(settings,
                       BoundingBox<dim>(std::make_pair(lower, upper)),
                       [](const Point<dim> &) { return true; },
                       {});
  }

  /// The resultant force and moment about the origin of the FE nodal forces @p F (all ranks).
  template <int dim>
  std::pair<Tensor<1, dim>, Tensor<1, 3>>
  fe_resultants(const perideal::FERegion<dim>                    &fe,
                const LinearAlgebra::distributed::Vector<double> &F)
  {
    std::map<types::global_dof_index, Point<dim>> support;
    DoFTools::map_dofs_to_support_points(hp::MappingCollection<dim>(MappingQ1<dim>()),
                                         fe.get_dof_handler(),
                                         support);
    Tensor<1, dim> force;
    Tensor<1, 3>   moment;
    const auto     owned = fe.get_dof_handler().locally_owned_dofs();
    for (unsigned int c = 0; c < dim; ++c)
      {
        std::vector<bool> mask(dim, false);
        mask[c]                 = true;
        const IndexSet selected = DoFTools::extract_dofs(fe.get_dof_handler(), ComponentMask(mask));
        for (const auto dof : selected)
          if (owned.is_element(dof))
            {
              Tensor<1, dim> nodal;
              nodal[c] = F[dof];
              force += nodal;
              moment += moment_of(support.at(dof), nodal);
            }
      }
    const MPI_Comm comm = MPI_COMM_WORLD;
    return {Utilities::MPI::sum(force, comm), Utilities::MPI::sum(moment, comm)};
  }

  template <int dim>
  void
  run(const unsigned int degree)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    std::cout << dim << "D, FE_Q(" << degree << ")" << std::endl;
    perideal::FERegion<dim> fe(comm);
    make_fe(fe, degree);

    perideal::ParticleSystem<dim> particles(comm);
    generate_particles(particles, 0.03, 0.1);

    perideal::TransferOperator<dim> transfer;
    transfer.reinit(fe, particles, fe.field_layout());

    // Slaved: the particles in cells with x < 0.0625 (cells of width 0.0125 that the weight
    // reaches).
    unsigned int mismatched = 0;
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      mismatched += (transfer.is_slaved(i) != (particles.positions()[i][0] < 0.0625));
    std::cout << "particles " << particles.n_global() << ", slaved " << transfer.n_global_slaved()
              << ", slaved exactly those in FE cells: "
              << (Utilities::MPI::sum(mismatched, comm) == 0 ? "yes" : "NO") << std::endl;

    // A linear field.
    LinearAlgebra::distributed::Vector<double> U;
    fe.initialize_vector(U);
    VectorTools::interpolate(fe.get_dof_handler(), LinearField<dim>(), U);
    perideal::ParticleVector u;
    particles.reinit_vector(u, dim);
    transfer.interpolate(U, u);
    double                 error = 0.;
    const LinearField<dim> field;
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      if (transfer.is_slaved(i))
        for (unsigned int c = 0; c < dim; ++c)
          error = std::max(error,
                           std::abs(u.local_element(i * dim + c) -
                                    field.value(particles.positions()[i], c)));
    error = Utilities::MPI::max(error, comm);
    std::cout << "linear field at slaved particles: max error / max value "
              << (error / 1e-4 < 1e-11 ? "< 1e-11" : "TOO LARGE") << std::endl;

    // Forces and moments.
    perideal::ParticleVector f;
    particles.reinit_vector(f, dim);
    Tensor<1, dim> force_p;
    double         moment_p = 0.;
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      if (transfer.is_slaved(i))
        {
          const auto g = particles.global_index(i);
          for (unsigned int c = 0; c < dim; ++c)
            f.local_element(i * dim + c) = std::sin(1. + g + 0.3 * c);
          const Point<dim> &x = particles.positions()[i];
          for (unsigned int c = 0; c < dim; ++c)
            force_p[c] += f.local_element(i * dim + c);
          moment_p += x[0] * f.local_element(i * dim + 1) - x[1] * f.local_element(i * dim);
        }
    LinearAlgebra::distributed::Vector<double> F;
    fe.initialize_vector(F);
    transfer.add_transpose(f, F);
    const auto [force_fe, moment_fe_vector] = fe_resultants(fe, F);
    const double moment_fe                  = moment_fe_vector[2];
    force_p                                 = Utilities::MPI::sum(force_p, comm);
    moment_p                                = Utilities::MPI::sum(moment_p, comm);
    std::cout << "force balance |sum F - sum f| / |sum f|: "
              << ((force_fe - force_p).norm() / force_p.norm() < 1e-12 ? "< 1e-12" : "VIOLATED")
              << ", moment balance: "
              << (std::abs(moment_fe - moment_p) / std::abs(moment_p) < 1e-12 ? "< 1e-12" :
                                                                                "VIOLATED")
              << std::endl;
  }

  /// Particles with rotations over the FE translations of make_fe().
  template <int dim>
  void
  run_micropolar(const unsigned int degree)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    std::cout << dim << "D, FE_Q(" << degree << "), particles with rotations" << std::endl;
    perideal::FERegion<dim> fe(comm);
    make_fe(fe, degree);
    perideal::ParticleSystem<dim> particles(comm);
    generate_particles(particles, 0.03, 0.1);
    const auto                      layout = perideal::FieldLayout::displacement_and_rotation(dim);
    const unsigned int              nc     = layout.n_components();
    perideal::TransferOperator<dim> transfer;
    transfer.reinit(fe, particles, layout);
    std::cout << "slaved " << transfer.n_global_slaved() << ", rows per particle "
              << transfer.n_point_components() << " (" << layout.names() << ")" << std::endl;

    // The linear field: translations and rotations at the slaved particles.
    LinearAlgebra::distributed::Vector<double> U;
    fe.initialize_vector(U);
    VectorTools::interpolate(fe.get_dof_handler(), LinearField<dim>(), U);
    perideal::ParticleVector u;
    particles.reinit_vector(u, nc);
    transfer.interpolate(U, u);
    const LinearField<dim> field;
    double                 translation_error = 0., rotation_error = 0.;
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      if (transfer.is_slaved(i))
        for (unsigned int c = 0; c < nc; ++c)
          {
            const double value = u.local_element(i * nc + c);
            if (layout.kind(c) == perideal::ComponentKind::translation)
              translation_error =
                std::max(translation_error,
                         std::abs(value - field.value(particles.positions()[i], c)));
            else
              rotation_error =
                std::max(rotation_error,
                         std::abs(value - linear_field_rotation<dim>(layout[c].axis)));
          }
    translation_error = Utilities::MPI::max(translation_error, comm);
    rotation_error    = Utilities::MPI::max(rotation_error, comm);
    std::cout << "linear field: translations "
              << (translation_error / 1e-4 < 1e-11 ? "exact" : "WRONG")
              << ", rotations 1/2 curl U: " << (rotation_error / 0.5e-3 < 1e-10 ? "exact" : "WRONG")
              << " (theta_z = " << linear_field_rotation<dim>(2) << ")" << std::endl;

    // Forces and moments on the slaved particles, their resultant and moment about the origin.
    perideal::ParticleVector f;
    particles.reinit_vector(f, nc);
    Tensor<1, dim> force_p;
    Tensor<1, 3>   moment_p, couples;
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      if (transfer.is_slaved(i))
        {
          const auto     g = particles.global_index(i);
          Tensor<1, dim> force;
          for (unsigned int c = 0; c < nc; ++c)
            {
              const double value          = std::sin(1. + g + 0.3 * c);
              f.local_element(i * nc + c) = value;
              if (layout.kind(c) == perideal::ComponentKind::translation)
                force[layout[c].axis] = value;
              else
                couples[layout[c].axis] += value;
            }
          force_p += force;
          moment_p += moment_of(particles.positions()[i], force);
        }
    LinearAlgebra::distributed::Vector<double> F;
    fe.initialize_vector(F);
    transfer.add_transpose(f, F);
    const auto [force_fe, moment_fe] = fe_resultants(fe, F);
    force_p                          = Utilities::MPI::sum(force_p, comm);
    moment_p                         = Utilities::MPI::sum(moment_p, comm);
    couples                          = Utilities::MPI::sum(couples, comm);
    const Tensor<1, 3> moment_total  = moment_p + couples;
    std::cout << "P^T: force balance "
              << ((force_fe - force_p).norm() / force_p.norm() < 1e-12 ? "< 1e-12" : "VIOLATED")
              << ", moment balance with the couples "
              << ((moment_fe - moment_total).norm() / moment_total.norm() < 1e-12 ? "< 1e-12" :
                                                                                    "VIOLATED")
              << " (the couples are "
              << (couples.norm() / moment_total.norm() > 1e-3 ? "> 1e-3" : "< 1e-3, TOO SMALL")
              << " of the total moment: the rotation rows carry them)" << std::endl;
  }

  /// A scalar particle field cannot follow FE translations.
  void
  mismatched_layouts()
  {
    const MPI_Comm        comm = MPI_COMM_WORLD;
    perideal::FERegion<2> fe(comm);
    make_fe(fe, 1);
    perideal::ParticleSystem<2> particles(comm);
    generate_particles(particles, 0.03, 0.1);
    perideal::TransferOperator<2> transfer;
    try
      {
        transfer.reinit(fe, particles, perideal::FieldLayout::scalar("w"));
        std::cout << "a scalar field over FE translations accepted: FAILED" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        std::cout << "a scalar field over FE translations refused: "
                  << perideal_tests::exception_text(exc) << std::endl;
      }
  }

  void
  outside_mesh()
  {
    const MPI_Comm        comm = MPI_COMM_WORLD;
    perideal::FERegion<2> fe(comm);
    make_fe(fe, 1);
    perideal::ParticleSystem<2> particles(comm);
    generate_particles(particles, 0.05, 0.11);
    perideal::TransferOperator<2> transfer;
    try
      {
        transfer.reinit(fe, particles, fe.field_layout());
        std::cout << "particles outside the mesh accepted: FAILED" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        const std::string text = perideal_tests::exception_text(exc);
        std::cout << "particles outside the mesh refused: " << text.substr(text.find("particle(s)"))
                  << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  run<2>(1);
  run<2>(2);
  run<3>(1);
  run_micropolar<2>(1);
  run_micropolar<2>(2);
  run_micropolar<3>(1);
  mismatched_layouts();
  outside_mesh();
}
