#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/hdf5_xdmf_writer.h>
#include <perideal/base/particle_output.h>

#include <filesystem>
#include <fstream>
#include <memory>

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
    this->points = points;
  }



  template <int dim>
  void
  ParticleOutput<dim>::add_scalar_field(const std::string &name, const std::vector<double> &values)
  {
    add_vector_field(name, 1, values);
  }



  template <int dim>
  void
  ParticleOutput<dim>::add_vector_field(const std::string         &name,
                                        const unsigned int         n_components,
                                        const std::vector<double> &values)
  {
    AssertThrow(n_components >= 1 && n_components <= dim + 3,
                dealii::ExcMessage("The field <" + name + "> has " + std::to_string(n_components) +
                                   " components; the accepted range is 1 to " +
                                   std::to_string(dim + 3) + "."));
    AssertThrow(!name.empty(), dealii::ExcMessage("Output fields need a non-empty name."));
    for (const auto &field : fields)
      AssertThrow(field.name != name,
                  dealii::ExcMessage("The output field <" + name + "> was added twice."));
    fields.push_back(Field{name, n_components, values});
  }



  template <int dim>
  void
  ParticleOutput<dim>::clear_fields()
  {
    fields.clear();
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
  ParticleOutput<dim>::build_patches()
  {
    // Check the sizes now, when the number of points is final.
    for (const auto &field : fields)
      AssertThrow(field.values.size() == field.n_components * points.size(),
                  dealii::ExcMessage("The output field <" + field.name + "> has " +
                                     std::to_string(field.values.size()) +
                                     " values, but there are " + std::to_string(points.size()) +
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

    const unsigned int n_rows = dataset_names.size();
#ifdef DEBUG
    // The writers are collective: all ranks need the same fields.
    Assert(dealii::Utilities::MPI::min(n_rows, comm) == dealii::Utilities::MPI::max(n_rows, comm),
           dealii::ExcMessage("All ranks must add the same output fields "
                              "before ParticleOutput::write()."));
#endif
    patches.clear();
    patches.resize(points.size());
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        auto &patch                = patches[p];
        patch.vertices[0]          = points[p];
        patch.patch_index          = p;
        patch.points_are_available = false;
        patch.data.reinit(n_rows, 1);
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
    build_patches();

    if (hdf5_xdmf_enabled)
      write_hdf5_xdmf(step, time);
    if (vtu_enabled)
      write_vtu_files(step, time);
  }



  template <int dim>
  void
  ParticleOutput<dim>::write_hdf5_xdmf(const unsigned int step, const double time)
  {
    // The patches keep their values in single precision (deal.II 9.4's Patch::data): the
    // filter takes the nodes from patches without values and the values from #fields, so that
    // the data sets (declared double, XDMF Precision="8") hold the doubles themselves.
    const auto fill_filter = [this](dealii::DataOutBase::DataOutFilter &filter) {
      std::vector<dealii::DataOutBase::Patch<0, dim>> nodes(patches.size());
      for (unsigned int p = 0; p < patches.size(); ++p)
        {
          nodes[p].vertices[0]          = patches[p].vertices[0];
          nodes[p].patch_index          = p;
          nodes[p].points_are_available = false;
        }
      dealii::DataOutBase::write_filtered_data(nodes, {}, {}, filter);

      dealii::Table<2, double> values(dataset_names.size(), points.size());
      unsigned int             row = 0;
      for (const auto &field : fields)
        for (unsigned int c = 0; c < field.n_components; ++c, ++row)
          for (unsigned int p = 0; p < points.size(); ++p)
            values(row, p) = field.values[p * field.n_components + c];
      // The data sets of build_patches(): a field of dim components as one vector, the others
      // by component.
      row = 0;
      for (const auto &field : fields)
        if (field.n_components == dim)
          {
            filter.write_data_set(field.name, dim, row, values);
            row += dim;
          }
        else
          for (unsigned int c = 0; c < field.n_components; ++c, ++row)
            filter.write_data_set(dataset_names[row], 1, row, values);
    };
    // Do not merge coincident vertices: two particles at the same position are still two.
    write_hdf5_xdmf_step(*this,
                         !patches.empty(),
                         false,
                         comm,
                         directory,
                         base_name,
                         step,
                         time,
                         xdmf_entries,
                         fill_filter);
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
