// ParticleOutput writes HDF5/XDMF and VTU for 7 particles split over the ranks in three ways
// (last rank empty, first rank empty, round robin); the files read back give the exact sums,
// and the HDF5 data sets hold the values in double precision, as their XDMF record declares.

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/particle_output.h>

#include "../tests.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <hdf5.h>


namespace
{
  constexpr unsigned int n_particles = 7;

  enum class Split
  {
    last_rank_empty,
    first_rank_empty,
    round_robin
  };

  std::string
  split_name(const Split split)
  {
    switch (split)
      {
        case Split::last_rank_empty:
          return "last_rank_empty";
        case Split::first_rank_empty:
          return "first_rank_empty";
        default:
          return "round_robin";
      }
  }

  // Global ids of the particles owned by this rank.
  std::vector<unsigned int>
  owned_ids(const Split split, const unsigned int rank, const unsigned int n_ranks)
  {
    std::vector<unsigned int> ids;
    for (unsigned int i = 0; i < n_particles; ++i)
      if ((split == Split::last_rank_empty && rank == 0) ||
          (split == Split::first_rank_empty && rank == n_ranks - 1) ||
          (split == Split::round_robin && i % n_ranks == rank))
        ids.push_back(i);
    return ids;
  }

  // Read a 2d double data set of an HDF5 file; returns the values row-major.
  std::vector<double>
  read_dataset(const hid_t file, const std::string &name, hsize_t &n_rows, hsize_t &n_cols)
  {
    const hid_t dataset = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    AssertThrow(dataset >= 0, dealii::ExcMessage("missing data set " + name));
    const hid_t space = H5Dget_space(dataset);
    AssertThrow(H5Sget_simple_extent_ndims(space) == 2, dealii::ExcInternalError());
    hsize_t dims[2];
    H5Sget_simple_extent_dims(space, dims, nullptr);
    n_rows = dims[0];
    n_cols = dims[1];
    std::vector<double> values(n_rows * n_cols);
    if (!values.empty())
      AssertThrow(
        H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0,
        dealii::ExcInternalError());
    H5Sclose(space);
    H5Dclose(dataset);
    return values;
  }

  unsigned int
  count_occurrences(const std::string &text, const std::string &word)
  {
    unsigned int n = 0;
    for (auto pos = text.find(word); pos != std::string::npos; pos = text.find(word, pos + 1))
      ++n;
    return n;
  }

  // Sum of the integer values of all attributes name="..." in an XML text.
  unsigned int
  sum_attribute(const std::string &text, const std::string &name)
  {
    const std::string key = name + "=\"";
    unsigned int      sum = 0;
    for (auto pos = text.find(key); pos != std::string::npos; pos = text.find(key, pos + 1))
      sum += std::stoul(text.substr(pos + key.size()));
    return sum;
  }

  std::string
  read_text(const std::string &filename)
  {
    std::ifstream     in(filename);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
  }

  template <int dim>
  void
  test(const Split split)
  {
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const std::string  name    = split_name(split) + "_" + std::to_string(dim) + "d";
    const std::string  dir     = "particle_output_01_data";

    perideal::ParticleOutput<dim> output(MPI_COMM_WORLD, dir, name, true, true);

    // Particle i sits at (0.5 i, 0.25 i, 0.125 i); at step s its damage is 0.125 i (s+1), its
    // displacement (0.5 i, -0.25 i, 1) (s+1) and its dim+1 components "extra" (i, 2i, ...).
    // With sum_i i = 21 and sum_i i^2 = 91 (i = 0..6) the files must give: sum x = 10.5,
    // sum damage = 2.625 (s+1), sum damage*x = 5.6875 (s+1), displacement sums
    // (10.5, -5.25, 7 or 0 in 2d) (s+1), extra sums 21 (c+1).
    const std::vector<unsigned int> ids = owned_ids(split, rank, n_ranks);
    std::vector<dealii::Point<dim>> points;
    for (const unsigned int i : ids)
      {
        dealii::Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = 0.5 * i / (1 << d);
        points.push_back(p);
      }
    for (unsigned int step = 0; step < 2; ++step)
      {
        std::vector<double> damage, displacement, extra;
        for (const unsigned int i : ids)
          {
            damage.push_back(0.125 * i * (step + 1));
            displacement.push_back(0.5 * i * (step + 1));
            displacement.push_back(-0.25 * i * (step + 1));
            if (dim == 3)
              displacement.push_back(1. * (step + 1));
            for (unsigned int c = 0; c < dim + 1; ++c)
              extra.push_back((c + 1.) * i);
          }
        // write() consumes the points and the fields: both again for each step.
        output.set_points(points);
        output.add_scalar_field("damage", damage);
        output.add_vector_field("displacement", dim, displacement);
        output.add_vector_field("extra", dim + 1, extra);
        output.write(step, 1e-6 * step);
      }

    if (rank != 0)
      return;

    dealii::deallog.push(name);
    for (unsigned int step = 0; step < 2; ++step)
      {
        const hid_t file = H5Fopen(output.hdf5_filename(step).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        AssertThrow(file >= 0, dealii::ExcMessage("cannot open " + output.hdf5_filename(step)));

        hsize_t                   n_nodes, node_dim, n_rows, n_cols;
        const std::vector<double> nodes = read_dataset(file, "nodes", n_nodes, node_dim);
        dealii::deallog << "step " << step << ": nodes " << n_nodes << " x " << node_dim;

        const std::vector<double> damage = read_dataset(file, "damage", n_rows, n_cols);
        AssertThrow(n_rows == n_nodes && n_cols == 1, dealii::ExcInternalError());
        double sum_damage = 0., sum_damage_x = 0., sum_x = 0.;
        for (unsigned int p = 0; p < n_nodes; ++p)
          {
            sum_damage += damage[p];
            sum_damage_x += damage[p] * nodes[p * node_dim];
            sum_x += nodes[p * node_dim];
          }
        dealii::deallog << ", sum x " << sum_x << ", sum damage " << sum_damage << ", sum damage*x "
                        << sum_damage_x;

        const std::vector<double> displacement = read_dataset(file, "displacement", n_rows, n_cols);
        AssertThrow(n_rows == n_nodes, dealii::ExcInternalError());
        dealii::deallog << ", displacement width " << n_cols << " sums";
        for (unsigned int c = 0; c < n_cols; ++c)
          {
            double sum = 0.;
            for (unsigned int p = 0; p < n_nodes; ++p)
              sum += displacement[p * n_cols + c];
            dealii::deallog << ' ' << sum;
          }

        dealii::deallog << ", extra_c sums";
        for (unsigned int c = 0; c < dim + 1; ++c)
          {
            const std::vector<double> extra =
              read_dataset(file, "extra_" + std::to_string(c), n_rows, n_cols);
            AssertThrow(n_rows == n_nodes && n_cols == 1, dealii::ExcInternalError());
            double sum = 0.;
            for (const double e : extra)
              sum += e;
            dealii::deallog << ' ' << sum;
          }
        dealii::deallog << std::endl;
        H5Fclose(file);
      }

    const std::string xdmf = read_text(output.xdmf_filename());
    dealii::deallog << "xdmf: " << count_occurrences(xdmf, "<Time Value") << " time steps, "
                    << count_occurrences(xdmf, "Polyvertex") << " Polyvertex topologies with "
                    << sum_attribute(xdmf, "NumberOfElements") << " vertices, "
                    << count_occurrences(xdmf, "AttributeType=\"Vector\"") << " vector and "
                    << count_occurrences(xdmf, "AttributeType=\"Scalar\"") << " scalar attributes"
                    << std::endl;

    const std::string pvd = read_text(output.pvd_filename());
    dealii::deallog << "pvd: " << count_occurrences(pvd, "<DataSet") << " data sets" << std::endl;
    for (unsigned int step = 0; step < 2; ++step)
      {
        const std::string pvtu =
          read_text(dir + "/" + name + "_" + dealii::Utilities::int_to_string(step, 5) + ".pvtu");
        const std::string vtu =
          read_text(dir + "/" + name + "_" + dealii::Utilities::int_to_string(step, 5) + ".0.vtu");
        dealii::deallog << "step " << step << ": pvtu " << count_occurrences(pvtu, "<Piece ")
                        << " piece, displacement is a 3-vector: "
                        << (pvtu.find("Name=\"displacement\" NumberOfComponents=\"3\"") !=
                                std::string::npos ?
                              "yes" :
                              "no")
                        << "; vtu points " << sum_attribute(vtu, "NumberOfPoints") << std::endl;
      }
    dealii::deallog.pop();
  }

  // No rank owns a particle: there is no HDF5 file to write (and deal.II cannot write an empty
  // one), but the VTU record still lists every step.
  void
  test_no_particles()
  {
    const std::string           dir = "particle_output_01_data";
    perideal::ParticleOutput<3> output(MPI_COMM_WORLD, dir, "no_particles", true, true);
    for (unsigned int step = 0; step < 2; ++step)
      {
        output.add_scalar_field("damage", {});
        output.add_vector_field("displacement", 3, {});
        output.write(step, 1e-6 * step);
      }
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      dealii::deallog << "no particles: h5 written "
                      << std::ifstream(output.hdf5_filename(0)).good() << ", xdmf written "
                      << std::ifstream(output.xdmf_filename()).good() << ", pvd data sets "
                      << count_occurrences(read_text(output.pvd_filename()), "<DataSet")
                      << std::endl;
  }

  // Values that single precision rounds (0.1 (i + 1)) read back bit for bit from the HDF5 file,
  // and every floating-point data item of the XDMF record (nodes, values) declares Precision="8"
  // (doubles).
  void
  test_precision()
  {
    const unsigned int            rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const unsigned int            n_ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    perideal::ParticleOutput<2>   output(MPI_COMM_WORLD,
                                       "particle_output_01_data",
                                       "precision",
                                       true,
                                       false);
    std::vector<dealii::Point<2>> points;
    std::vector<double>           values;
    for (const unsigned int i : owned_ids(Split::round_robin, rank, n_ranks))
      {
        points.emplace_back(0.5 * i, 0.);
        values.push_back(0.1 * (i + 1));
      }
    output.set_points(points);
    output.add_scalar_field("value", values);
    output.write(0, 0.);
    if (rank != 0)
      return;
    const hid_t file = H5Fopen(output.hdf5_filename(0).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    AssertThrow(file >= 0, dealii::ExcMessage("cannot open " + output.hdf5_filename(0)));
    hsize_t                   n_nodes, node_dim, n_rows, n_cols;
    const std::vector<double> nodes = read_dataset(file, "nodes", n_nodes, node_dim);
    const std::vector<double> read  = read_dataset(file, "value", n_rows, n_cols);
    H5Fclose(file);
    unsigned int n_exact = 0;
    for (unsigned int p = 0; p < n_nodes; ++p)
      {
        // Particle i sits at x = 0.5 i.
        const auto i = static_cast<unsigned int>(std::lround(2. * nodes[p * node_dim]));
        n_exact += (read[p] == 0.1 * (i + 1));
      }
    const std::string xdmf = read_text(output.xdmf_filename());
    dealii::deallog << "precision: " << n_exact << " of " << n_nodes
                    << " values 0.1 (i + 1) read back exactly; XDMF Precision=\"8\" on "
                    << count_occurrences(xdmf, "Precision=\"8\"") << " of "
                    << count_occurrences(xdmf, "NumberType=\"Float\"")
                    << " floating-point data items" << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  for (const Split split : {Split::last_rank_empty, Split::first_rank_empty, Split::round_robin})
    {
      test<2>(split);
      test<3>(split);
    }
  test_no_particles();
  test_precision();
}
