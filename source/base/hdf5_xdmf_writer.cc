// ---------------------------------------------------------------------
// PeriDeal: one time step of parallel HDF5 output plus its XDMF record.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/hdf5.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/hdf5_xdmf_writer.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <unordered_map>

namespace perideal
{
  namespace
  {
    // A point as the key of a hash map: the bits of its coordinates, with -0 as +0 (the
    // filter's ordered map takes them as equal).
    template <int spacedim>
    using PointKey = std::array<std::uint64_t, spacedim>;

    template <int spacedim>
    PointKey<spacedim>
    point_key(const dealii::Point<spacedim> &p)
    {
      PointKey<spacedim> key;
      for (unsigned int d = 0; d < spacedim; ++d)
        {
          const double x = p[d] + 0.;
          std::memcpy(&key[d], &x, sizeof(double));
        }
      return key;
    }

    template <int spacedim>
    struct PointKeyHash
    {
      std::size_t
      operator()(const PointKey<spacedim> &key) const
      {
        std::uint64_t h = 0x9e3779b97f4a7c15ULL;
        for (const std::uint64_t k : key)
          {
            h ^= k + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
            h = (h ^ (h >> 31)) * 0xbf58476d1ce4e5b9ULL;
          }
        return h;
      }
    };
  } // namespace



  template <int dim, int spacedim>
  HDF5StepData<spacedim>
  merged_step_data(const std::vector<dealii::DataOutBase::Patch<dim, spacedim>> &patches,
                   const std::vector<std::string>                               &names,
                   const NonscalarDataRanges                                    &vectors)
  {
    HDF5StepData<spacedim> result;
    result.cell_dim = dim;
    if (patches.empty())
      return result;

    // The points of a patch of one subdivision are its vertices, in deal.II's (lexicographic)
    // order, which the point data's columns follow.
    constexpr unsigned int    n_vertices = dealii::GeometryInfo<dim>::vertices_per_cell;
    std::vector<unsigned int> node_of_point(patches.size() * n_vertices);
    std::unordered_map<PointKey<spacedim>, unsigned int, PointKeyHash<spacedim>> nodes;
    nodes.reserve(node_of_point.size());
    for (unsigned int p = 0; p < patches.size(); ++p)
      {
        const auto &patch = patches[p];
        AssertThrow(patch.n_subdivisions == 1 && !patch.points_are_available &&
                      patch.reference_cell == dealii::ReferenceCells::get_hypercube<dim>(),
                    dealii::ExcMessage("The HDF5 output takes hypercube patches of one "
                                       "subdivision whose points are their vertices."));
        for (unsigned int v = 0; v < n_vertices; ++v)
          {
            const auto [it, inserted] = nodes.emplace(point_key(patch.vertices[v]), nodes.size());
            if (inserted)
              for (unsigned int d = 0; d < spacedim; ++d)
                result.nodes.push_back(patch.vertices[v][d]);
            node_of_point[p * n_vertices + v] = it->second;
          }
      }

    // XDMF's quadrilaterals and hexahedra go round each face, deal.II's vertices are
    // lexicographic.
    constexpr std::array<unsigned int, 8> xdmf_order = {{0, 1, 3, 2, 4, 5, 7, 6}};
    result.cells.reserve(node_of_point.size());
    for (unsigned int p = 0; p < patches.size(); ++p)
      for (unsigned int v = 0; v < n_vertices; ++v)
        result.cells.push_back(node_of_point[p * n_vertices + xdmf_order[v]]);

    // The data sets in the filter's order: a vector where one starts, a scalar otherwise. Each
    // row of the point data goes to one component of one data set.
    struct Target
    {
      unsigned int set, component;
    };
    std::vector<Target> targets;
    for (unsigned int row = 0; row < names.size();)
      {
        typename HDF5StepData<spacedim>::DataSet set{names[row], 1, {}};
        unsigned int                             n_components = 1;
        for (const auto &range : vectors)
          if (std::get<0>(range) == row)
            {
              n_components = std::get<1>(range) - row + 1;
              AssertThrow(n_components <= 3,
                          dealii::ExcMessage("The HDF5 output writes vectors of at most three "
                                             "components (<" +
                                             std::get<2>(range) + "> has " +
                                             std::to_string(n_components) + ")."));
              set.width = 3;
              if (!std::get<2>(range).empty())
                set.name = std::get<2>(range);
            }
        set.values.assign(result.n_nodes() * set.width, 0.);
        for (unsigned int c = 0; c < n_components; ++c)
          targets.push_back({static_cast<unsigned int>(result.data_sets.size()), c});
        result.data_sets.push_back(std::move(set));
        row += n_components;
      }
    // Patch by patch, so that each patch's values are read once and in order (the values of
    // a data set are spread over all patches' tables).
    for (unsigned int p = 0; p < patches.size(); ++p)
      for (unsigned int row = 0; row < targets.size(); ++row)
        {
          auto &set = result.data_sets[targets[row].set];
          for (unsigned int v = 0; v < n_vertices; ++v)
            set.values[node_of_point[p * n_vertices + v] * set.width + targets[row].component] =
              patches[p].data(row, v);
        }
    return result;
  }



  template <int spacedim>
  void
  write_hdf5_xdmf_step(HDF5StepData<spacedim>        &&data,
                       const MPI_Comm                  comm,
                       const std::string              &directory,
                       const std::string              &base_name,
                       const unsigned int              step,
                       const double                    time,
                       std::vector<dealii::XDMFEntry> &entries)
  {
    const unsigned int                 vertices_per_cell = 1U << data.cell_dim;
    const std::array<std::uint64_t, 2> local{
      {data.n_nodes(), data.cells.size() / vertices_per_cell}};
    std::array<std::uint64_t, 2> global{};
    dealii::Utilities::MPI::sum(dealii::ArrayView<const std::uint64_t>(local.data(), 2),
                                comm,
                                dealii::ArrayView<std::uint64_t>(global.data(), 2));
    if (global[0] == 0)
      return; // nothing to write anywhere
    AssertThrow(global[0] <= std::numeric_limits<unsigned int>::max(),
                dealii::ExcMessage("The HDF5 output numbers its nodes with 32 bits; this step "
                                   "has " +
                                   std::to_string(global[0]) + " nodes."));
    std::array<std::uint64_t, 2> offset{};
    const int ierr = MPI_Exscan(local.data(), offset.data(), 2, MPI_UINT64_T, MPI_SUM, comm);
    AssertThrowMPI(ierr);
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      offset = {}; // MPI_Exscan leaves the first rank's result undefined
    AssertThrow(std::filesystem::is_directory(directory),
                dealii::ExcMessage("The output directory <" + directory + "> does not exist."));

    // The XDMF record refers to the .h5 file relative to its own location.
    const std::string h5_name = base_name + "_" + dealii::Utilities::int_to_string(step, 5) + ".h5";
    {
      dealii::HDF5::File file(directory + "/" + h5_name,
                              dealii::HDF5::File::FileAccessMode::create,
                              comm);
      // One collective data set of rows of `width` values; a rank without rows writes none.
      const auto write = [&file](const std::string  &name,
                                 const auto         &values,
                                 const std::uint64_t n_rows_global,
                                 const std::uint64_t row_offset,
                                 const std::uint64_t width) {
        using Number = typename std::decay_t<decltype(values)>::value_type;
        auto set     = file.create_dataset<Number>(name, {n_rows_global, width});
        if (values.empty())
          set.template write_none<Number>();
        else
          set.write_hyperslab(values, {row_offset, 0}, {values.size() / width, width});
      };
      write("nodes", data.nodes, global[0], offset[0], spacedim);
      for (unsigned int &node : data.cells)
        node += offset[0];
      write("cells", data.cells, global[1], offset[1], vertices_per_cell);
      for (const auto &set : data.data_sets)
        write(set.name, set.values, global[0], offset[0], set.width);
    }

    dealii::XDMFEntry entry(h5_name, h5_name, time, global[0], global[1], data.cell_dim, spacedim);
    for (const auto &set : data.data_sets)
      entry.add_attribute(set.name, set.width);
    entries.push_back(entry);

    // The record as DataOutInterface::write_xdmf_file() writes it (which needs patches on the
    // writing rank).
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        const std::string name = directory + "/" + base_name + ".xdmf";
        std::ofstream     xdmf(name);
        AssertThrow(xdmf, dealii::ExcFileNotOpen(name));
        xdmf << "<?xml version=\"1.0\" ?>\n"
             << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
             << "<Xdmf Version=\"2.0\">\n"
             << "  <Domain>\n"
             << "    <Grid Name=\"CellTime\" GridType=\"Collection\" "
                "CollectionType=\"Temporal\">\n";
        const dealii::ReferenceCell cell =
          data.cell_dim == 0 ? dealii::ReferenceCells::Vertex :
          data.cell_dim == 2 ? dealii::ReferenceCells::Quadrilateral :
                               dealii::ReferenceCells::Hexahedron;
        for (const auto &e : entries)
          xdmf << e.get_xdmf_content(3, cell);
        xdmf << "    </Grid>\n"
             << "  </Domain>\n"
             << "</Xdmf>\n";
      }
  }

#define PERIDEAL_INSTANTIATE(dim)                              \
  template HDF5StepData<dim> merged_step_data(                 \
    const std::vector<dealii::DataOutBase::Patch<dim, dim>> &, \
    const std::vector<std::string> &,                          \
    const NonscalarDataRanges &);                              \
  template void write_hdf5_xdmf_step(HDF5StepData<dim> &&,     \
                                     const MPI_Comm,           \
                                     const std::string &,      \
                                     const std::string &,      \
                                     const unsigned int,       \
                                     const double,             \
                                     std::vector<dealii::XDMFEntry> &);
  PERIDEAL_INSTANTIATE(2)
  PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
} // namespace perideal
