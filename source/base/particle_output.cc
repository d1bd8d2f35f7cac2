#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/hdf5_xdmf_writer.h>
#include <perideal/base/particle_output.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <numeric>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

namespace perideal
{
  template <int dim>
  ParticleOutput<dim>::ParticleOutput(MPI_Comm           comm,
                                      const std::string &directory,
                                      const std::string &base_name,
                                      const bool         write_hdf5_xdmf,
                                      const bool         write_vtu)
    : comm(comm)
    , directory(directory.empty() ? std::string(".") : directory)
    , base_name(base_name)
    , hdf5_xdmf_enabled(write_hdf5_xdmf)
    , vtu_enabled(write_vtu)
  {
    AssertThrow(!base_name.empty(),
                dealii::ExcMessage("The base name of the particle output "
                                   "must not be empty."));

    int error = 0;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code ec;
        std::filesystem::create_directories(this->directory, ec);
        error = (ec || !std::filesystem::is_directory(this->directory)) ? 1 : 0;
      }
    error = dealii::Utilities::MPI::max(error, comm);
    AssertThrow(error == 0,
                dealii::ExcMessage("Could not create the output directory <" + this->directory +
                                   ">. Check the output directory parameter "
                                   "and the file system permissions."));
  }



  template <int dim>
  void
  ParticleOutput<dim>::set_points(const std::vector<dealii::Point<dim>> &points)
  {
    // Flat, as the HDF5 nodes are laid out (write() moves them there).
    coordinates.clear();
    coordinates.reserve(dim * points.size());
    for (const auto &point : points)
      for (unsigned int d = 0; d < dim; ++d)
        coordinates.push_back(point[d]);
  }



  template <int dim>
  void
  ParticleOutput<dim>::add_scalar_field(const std::string &name, std::vector<double> values)
  {
    add_vector_field(name, 1, std::move(values));
  }



  template <int dim>
  void
  ParticleOutput<dim>::add_vector_field(const std::string  &name,
                                        const unsigned int  n_components,
                                        std::vector<double> values)
  {
    AssertThrow(n_components >= 1 && n_components <= dim + 3,
                dealii::ExcMessage("The field <" + name + "> has " + std::to_string(n_components) +
                                   " components; the accepted range is 1 to " +
                                   std::to_string(dim + 3) + "."));
    AssertThrow(!name.empty(), dealii::ExcMessage("Output fields need a non-empty name."));
    for (const auto &field : fields)
      AssertThrow(field.name != name,
                  dealii::ExcMessage("The output field <" + name + "> was added twice."));
    fields.push_back(Field{name, n_components, std::move(values)});
  }



  template <int dim>
  std::string
  ParticleOutput<dim>::xdmf_filename() const
  {
    return directory + "/" + base_name + ".xdmf";
  }



  template <int dim>
  std::string
  ParticleOutput<dim>::hdf5_filename(const unsigned int step) const
  {
    return directory + "/" + base_name + "_" + dealii::Utilities::int_to_string(step, 5) + ".h5";
  }



  template <int dim>
  std::string
  ParticleOutput<dim>::pvd_filename() const
  {
    return directory + "/" + base_name + ".pvd";
  }



  template <int dim>
  void
  ParticleOutput<dim>::name_data_sets()
  {
    // Check the sizes now, when the number of points is final.
    const std::size_t n_points = coordinates.size() / dim;
    for (const auto &field : fields)
      AssertThrow(field.values.size() == field.n_components * n_points,
                  dealii::ExcMessage("The output field <" + field.name + "> has " +
                                     std::to_string(field.values.size()) +
                                     " values, but there are " + std::to_string(n_points) +
                                     " points with " + std::to_string(field.n_components) +
                                     " components each."));

    dataset_names.clear();
    vector_ranges.clear();
    for (const auto &field : fields)
      {
        const unsigned int first = dataset_names.size();
        if (field.n_components == 1)
          dataset_names.push_back(field.name);
        else if (field.n_components == dim)
          {
            for (unsigned int c = 0; c < dim; ++c)
              dataset_names.push_back(field.name);
            vector_ranges.emplace_back(
              first,
              first + dim - 1,
              field.name,
              dealii::DataComponentInterpretation::component_is_part_of_vector);
          }
        else
          for (unsigned int c = 0; c < field.n_components; ++c)
            dataset_names.push_back(field.name + "_" + std::to_string(c));
      }
#ifdef DEBUG
    // The writers are collective: all ranks need the same fields.
    const unsigned int n_rows = dataset_names.size();
    Assert(dealii::Utilities::MPI::min(n_rows, comm) == dealii::Utilities::MPI::max(n_rows, comm),
           dealii::ExcMessage("All ranks must add the same output fields "
                              "before ParticleOutput::write()."));
#endif
  }



  template <int dim>
  void
  ParticleOutput<dim>::build_patches()
  {
    patches.clear();
    patches.resize(coordinates.size() / dim);
    for (unsigned int p = 0; p < patches.size(); ++p)
      {
        auto &patch = patches[p];
        for (unsigned int d = 0; d < dim; ++d)
          patch.vertices[0][d] = coordinates[dim * p + d];
        patch.patch_index          = p;
        patch.points_are_available = false;
        patch.data.reinit(dataset_names.size(), 1);
        unsigned int row = 0;
        for (const auto &field : fields)
          for (unsigned int c = 0; c < field.n_components; ++c, ++row)
            patch.data(row, 0) = static_cast<float>(field.values[p * field.n_components + c]);
      }
  }



  template <int dim>
  const std::vector<dealii::DataOutBase::Patch<0, dim>> &
  ParticleOutput<dim>::get_patches() const
  {
    return patches;
  }



  template <int dim>
  std::vector<std::string>
  ParticleOutput<dim>::get_dataset_names() const
  {
    return dataset_names;
  }



  template <int dim>
  std::vector<std::tuple<unsigned int,
                         unsigned int,
                         std::string,
                         dealii::DataComponentInterpretation::DataComponentInterpretation>>
  ParticleOutput<dim>::get_nonscalar_data_ranges() const
  {
    return vector_ranges;
  }



  template <int dim>
  void
  ParticleOutput<dim>::write(const unsigned int step, const double time)
  {
    name_data_sets();
    if (vtu_enabled)
      {
        build_patches();
        write_vtu_files(step, time);
        patches = {};
      }
    // Moves the coordinates and the fields' values into its data sets.
    if (hdf5_xdmf_enabled)
      write_hdf5_xdmf(step, time);
    coordinates = {};
    fields.clear();
  }



  template <int dim>
  void
  ParticleOutput<dim>::write_hdf5_xdmf(const unsigned int step, const double time)
  {
    // The values in double precision from #fields (the patches keep single precision, deal.II
    // 9.4's Patch::data), moved where the layout is the same; one node and one vertex cell per
    // particle, coincident ones not merged (two particles at the same position are still two).
    const unsigned int n_points = coordinates.size() / dim;
    HDF5StepData<dim>  data;
    data.cell_dim = 0;
    data.nodes    = std::move(coordinates);
    data.cells.resize(n_points);
    std::iota(data.cells.begin(), data.cells.end(), 0U);
    // The data sets of name_data_sets(): a field of dim components as one vector (three values
    // per node: a 2D vector's third is zero), the others by component.
    using DataSet    = typename HDF5StepData<dim>::DataSet;
    unsigned int row = 0;
    for (auto &field : fields)
      {
        if (field.n_components == 1 || (field.n_components == dim && dim == 3))
          data.data_sets.push_back(
            DataSet{dataset_names[row], field.n_components, std::move(field.values)});
        else if (field.n_components == dim)
          {
            DataSet set{field.name, 3, std::vector<double>(3 * n_points)};
            for (unsigned int p = 0; p < n_points; ++p)
              for (unsigned int d = 0; d < dim; ++d)
                set.values[3 * p + d] = field.values[dim * p + d];
            data.data_sets.push_back(std::move(set));
          }
        else
          for (unsigned int c = 0; c < field.n_components; ++c)
            {
              DataSet set{dataset_names[row + c], 1, std::vector<double>(n_points)};
              for (unsigned int p = 0; p < n_points; ++p)
                set.values[p] = field.values[field.n_components * p + c];
              data.data_sets.push_back(std::move(set));
            }
        row += field.n_components;
        field.values = {};
      }
    write_hdf5_xdmf_step(std::move(data), comm, directory, base_name, step, time, xdmf_entries);
  }



  template <int dim>
  void
  ParticleOutput<dim>::write_vtu_files(const unsigned int step, const double time)
  {
    const std::string pvtu_name =
      this->write_vtu_with_pvtu_record(directory + "/", base_name, step, comm, 5, 1);

    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        pvd_records.emplace_back(time, pvtu_name);
        std::ofstream pvd(pvd_filename());
        AssertThrow(pvd, dealii::ExcFileNotOpen(pvd_filename()));
        dealii::DataOutBase::write_pvd_record(pvd, pvd_records);
      }
  }



  template <int dim>
  std::string
  ParticleOutput<dim>::save_records() const
  {
    const std::vector<char> packed =
      dealii::Utilities::pack(std::make_pair(xdmf_entries, pvd_records), false);
    return std::string(packed.begin(), packed.end());
  }

  template <int dim>
  void
  ParticleOutput<dim>::load_records(const std::string &packed)
  {
    std::tie(xdmf_entries, pvd_records) = dealii::Utilities::unpack<
      std::pair<std::vector<dealii::XDMFEntry>, std::vector<std::pair<double, std::string>>>>(
      std::vector<char>(packed.begin(), packed.end()),
      false);
  }

  template class ParticleOutput<2>;
  template class ParticleOutput<3>;
} // namespace perideal
