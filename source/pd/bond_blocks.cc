// ---------------------------------------------------------------------
// PeriDeal: lattice bond blocks of the force kernels.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <perideal/base/setup_times.h>
#include <perideal/pd/bond_blocks.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  BondBlocks<dim>::reinit(const ParticleSystem<dim> &particles)
  {
    const SetupTimes::Scope time(SetupStage::kernel_blocks);

    const BondList &bonds     = particles.bonds();
    const auto     &positions = particles.positions();
    const double    dx        = particles.settings().spacing;
    n_owned                   = particles.n_owned();
    n_local                   = particles.n_local();

    // Lattice coordinates of the local particles (of their lattice points on a perturbed
    // lattice, whose offsets are at most perturbation / 2 spacings per coordinate).
    std::vector<std::array<long, dim>> lattice(n_local);
    for (unsigned int i = 0; i < n_local; ++i)
      lattice[i] = particles.lattice().index_of(positions[i]);

    // Kernel order: lexicographic, the last coordinate slowest.
    std::vector<unsigned int> order(n_local);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      for (unsigned int d = dim; d-- > 0;)
        if (lattice[a][d] != lattice[b][d])
          return lattice[a][d] < lattice[b][d];
      return false;
    });
    // Kernel slots: the particles in that order, in windows of width consecutive points of the
    // global lattice box (its linear index, the first coordinate fastest, divided by width),
    // each window a group of its own. A group then holds the same lattice points on any number of
    // ranks (those of them that are local), so every particle receives its bonds'
    // contributions in the same order and its force is the same to the last bit on any
    // partition (doc/architecture/06_force_kernels.md, "The same sums on any partition").
    // Where the local particles fill the box the slots are the dense order (no empty slot); the
    // slots of absent points in a window are empty lanes, and absent windows are skipped.
    std::array<unsigned long long, dim> stride;
    for (unsigned int d = 0; d < dim; ++d)
      stride[d] = d == 0 ? 1ull : stride[d - 1] * particles.lattice().n_points(d - 1);
    const auto linear_index = [&](const std::array<long, dim> &p) {
      unsigned long long index = 0;
      for (unsigned int d = 0; d < dim; ++d)
        index += static_cast<unsigned long long>(p[d]) * stride[d];
      return index;
    };
    kernel_index.assign(n_local, 0);
    std::size_t slot = 0;
    for (unsigned int k = 0; k < n_local; ++k)
      {
        const unsigned long long index = linear_index(lattice[order[k]]);
        if (k == 0)
          slot = index % width;
        else
          {
            const unsigned long long previous = linear_index(lattice[order[k - 1]]);
            if (previous / width == index / width)
              slot += index - previous;
            else
              slot = (slot / width + 1) * width + index % width;
          }
        kernel_index[order[k]] = slot;
      }
    n_slots = n_local == 0 ? 0 : slot + 1;

    // Every bond is placed at its end with the lower kernel index (so offsets are positive and
    // a bond and its reverse share one class), even if that end is a ghost: the kernels add
    // equal and opposite forces to both ends and only the owned ones are kept. Each lattice
    // vector then has one class, and the blocks of a group fill their lanes well.
    const auto lattice_vector = [&](const unsigned int i, const unsigned int b) {
      const unsigned int    j = bonds.neighbor[b];
      std::array<long, dim> q;
      for (unsigned int d = 0; d < dim; ++d)
        q[d] = (kernel_index[i] < kernel_index[j] ? lattice[j][d] - lattice[i][d] :
                                                    lattice[i][d] - lattice[j][d]);
      return q;
    };

    // Bond classes (lattice vectors), ranked with the first component slowest so that the
    // neighbour ranges of consecutive blocks of a group are a lattice line apart: a dense table
    // over the box [-extent, extent]^dim of the vectors, enumerated in that (lexicographic) order.
    long extent = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        for (const long q : lattice_vector(i, b))
          extent = std::max(extent, std::abs(q));
    const long side       = 2 * extent + 1;
    const auto table_slot = [&](const std::array<long, dim> &q) {
      std::size_t slot = 0;
      for (unsigned int d = 0; d < dim; ++d)
        slot = slot * side + (q[d] + extent);
      return slot;
    };
    const unsigned int        none = numbers::invalid_unsigned_int;
    std::vector<unsigned int> class_of(std::size_t(std::pow(side, dim)), none);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        class_of[table_slot(lattice_vector(i, b))] = 0;
    class_list.clear();
    for (std::size_t slot = 0; slot < class_of.size(); ++slot)
      if (class_of[slot] != none)
        {
          class_of[slot] = class_list.size();
          BondClass   c;
          double      length2 = 0.;
          std::size_t rest    = slot;
          for (unsigned int d = dim; d-- > 0;)
            {
              c.xi[d] = (long(rest % side) - extent) * dx;
              rest /= side;
            }
          for (unsigned int d = 0; d < dim; ++d)
            length2 += c.xi[d] * c.xi[d];
          c.length         = std::sqrt(length2);
          c.inverse_length = 1. / c.length;
          class_list.push_back(c);
        }

    // The bonds bucketed by their group (the group of their end of lower kernel index): a
    // counting sort that holds one index per bond.
    const auto lower_end = [&](const unsigned int i, const unsigned int b) {
      return std::min(kernel_index[i], kernel_index[bonds.neighbor[b]]);
    };
    const std::size_t        n_groups = (n_slots + width - 1) / width;
    std::vector<std::size_t> group_start(n_groups + 1, 0);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        ++group_start[lower_end(i, b) / width + 1];
    std::partial_sum(group_start.begin(), group_start.end(), group_start.begin());
    std::vector<unsigned int> by_group(bonds.size());
    {
      std::vector<std::size_t> next(group_start.begin(), group_start.end() - 1);
      for (unsigned int i = 0; i < n_owned; ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          by_group[next[lower_end(i, b) / width]++] = b;
    }

    // Blocks: a group of width particles, one class, one offset; within a group, the blocks by
    // class, then offset.
    struct Pair
    {
      unsigned int bond_class;
      int          offset;
      unsigned int lane;
      unsigned int bond;
    };
    std::vector<Pair> pairs;
    group_list.clear();
    block_list.clear();
    lane_bond.clear();
    for (std::size_t group = 0; group < n_groups; ++group)
      {
        if (group_start[group] == group_start[group + 1])
          continue;
        pairs.clear();
        // A group's bonds are in the order of the rows (the counting sort ran over them in
        // order), a row's in a run: the row of a bond is its predecessor's or found after it.
        unsigned int i = 0;
        for (std::size_t k = group_start[group]; k < group_start[group + 1]; ++k)
          {
            const unsigned int b = by_group[k];
            if (k == group_start[group] || bonds.row_start[i + 1] <= b)
              i = std::upper_bound(bonds.row_start.begin() + i, bonds.row_start.end(), b) -
                  bonds.row_start.begin() - 1;
            const unsigned int j = bonds.neighbor[b];
            pairs.push_back({class_of[table_slot(lattice_vector(i, b))],
                             std::abs(int(kernel_index[j]) - int(kernel_index[i])),
                             lower_end(i, b) % width,
                             b});
          }
        std::sort(pairs.begin(), pairs.end(), [](const Pair &x, const Pair &y) {
          if (x.bond_class != y.bond_class)
            return x.bond_class < y.bond_class;
          if (x.offset != y.offset)
            return x.offset < y.offset;
          return x.lane < y.lane;
        });
        group_list.push_back(
          {static_cast<unsigned int>(group * width), static_cast<unsigned int>(block_list.size())});
        for (std::size_t s = 0; s < pairs.size();)
          {
            block_list.push_back({pairs[s].offset, pairs[s].bond_class});
            lane_bond.resize(lane_bond.size() + width, none);
            unsigned int *lanes = lane_bond.data() + lane_bond.size() - width;
            std::size_t   e     = s;
            for (; e < pairs.size() && pairs[e].bond_class == pairs[s].bond_class &&
                   pairs[e].offset == pairs[s].offset;
                 ++e)
              lanes[pairs[e].lane] = pairs[e].bond;
            s = e;
          }
      }
    by_group = std::vector<unsigned int>();
    // The lane arrays grew block by block: no spare capacity kept.
    lane_bond.shrink_to_fit();
    block_list.shrink_to_fit();
    group_list.push_back(
      {numbers::invalid_unsigned_int, static_cast<unsigned int>(block_list.size())});

    // Components of a field a multiple of 64 bytes but never close to a multiple of 4 KiB
    // apart: a load whose address matches an older store's in the low 12 bits waits for it
    // ("4K aliasing"), which made the kernel 25 times slower for unlucky particle counts.
    field_stride = (n_slots + width - 1) / width * width + 2 * width;
    field_stride += (168 - field_stride % 512 + 512) % 512;
    // The lanes' own reference bonds on a perturbed lattice (from the lane's particle, the end
    // of lower kernel index, to its neighbour, like the class's lattice vector): the kernels
    // form xi from the reference positions in kernel order (per particle, loaded like the
    // displacements), and stream only the inverse length per lane (8 B, not the 32 B of xi and
    // 1/|xi|; doc/benchmarks/performance/README.md, "Perturbed lattices").
    reference_position.clear();
    lane_inverse_length.clear();
    if (particles.settings().perturbation > 0.)
      {
        reinit_field(reference_position, dim);
        for (unsigned int d = 0; d < dim; ++d)
          {
            double           *x     = component(reference_position, d);
            double            x_max = 0.;
            std::vector<bool> held(field_stride, false);
            for (unsigned int i = 0; i < n_local; ++i)
              {
                x[kernel_index[i]]    = positions[i][d];
                held[kernel_index[i]] = true;
                x_max                 = std::max(x_max, std::abs(positions[i][d]));
              }
            // Entries no particle holds (the lanes without a bond read them): beyond the body,
            // one spacing apart, so that no lane's vector is zero.
            for (std::size_t k = 0; k + width < field_stride; ++k)
              if (!held[k])
                x[k] = x_max + double(k + 1) * dx;
          }
        const std::size_t n_lanes = lane_bond.size();
        lane_inverse_length.resize_fast(n_lanes);
        const double *x[dim];
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = component(reference_position, d);
        for (std::size_t g = 0; g + 1 < group_list.size(); ++g)
          for (std::size_t q = group_list[g].first_block; q < group_list[g + 1].first_block; ++q)
            for (unsigned int l = 0; l < width; ++l)
              {
                // Lane l is particle first + l, its neighbour first + offset + l.
                const std::size_t       lane  = q * width + l;
                const std::size_t       first = group_list[g].first_particle + l;
                std::array<double, dim> xi    = class_list[block_list[q].bond_class].xi;
                if (lane_bond[lane] != numbers::invalid_unsigned_int)
                  for (unsigned int d = 0; d < dim; ++d)
                    xi[d] = x[d][first + block_list[q].offset] - x[d][first];
                double length2 = 0.;
                for (unsigned int d = 0; d < dim; ++d)
                  length2 += xi[d] * xi[d];
                lane_inverse_length[lane] = 1. / std::sqrt(length2);
              }
      }
    lane_state.assign(lane_bond.size(), 0);
    synced_revision = bonds.revision() + 1;
    sync_state(bonds);
  }

  template <int dim>
  void
  BondBlocks<dim>::to_lanes(const std::vector<double> &per_bond, Array &per_lane) const
  {
    per_lane.resize_fast(lane_bond.size());
    for (std::size_t l = 0; l < lane_bond.size(); ++l)
      per_lane[l] = (lane_bond[l] == numbers::invalid_unsigned_int ? 0. : per_bond[lane_bond[l]]);
  }

  template <int dim>
  void
  BondBlocks<dim>::to_lanes(
    const BondList                                                     &bonds,
    const std::function<double(const unsigned int, const std::size_t)> &value,
    Array                                                              &per_lane) const
  {
    // A lane's bond joins its particle (kernel index first + l) and the one offset further;
    // its row is the end that is not its neighbour.
    std::vector<unsigned int> particle_at(n_slots);
    for (unsigned int i = 0; i < n_local; ++i)
      particle_at[kernel_index[i]] = i;
    per_lane.resize_fast(lane_bond.size());
    for (std::size_t g = 0; g + 1 < group_list.size(); ++g)
      for (std::size_t q = group_list[g].first_block; q < group_list[g + 1].first_block; ++q)
        for (unsigned int l = 0; l < width; ++l)
          {
            const std::size_t  lane = q * width + l;
            const unsigned int b    = lane_bond[lane];
            if (b == numbers::invalid_unsigned_int)
              {
                per_lane[lane] = 0.;
                continue;
              }
            const unsigned int near = particle_at[group_list[g].first_particle + l];
            const unsigned int i =
              bonds.neighbor[b] == near ?
                particle_at[group_list[g].first_particle + l + block_list[q].offset] :
                near;
            per_lane[lane] = value(i, b);
          }
  }

  template <int dim>
  std::size_t
  BondBlocks<dim>::lane_of(const BondList &bonds, const unsigned int i, const std::size_t b) const
  {
    const unsigned int ki = kernel_index[i], kj = kernel_index[bonds.neighbor[b]];
    const unsigned int a      = std::min(ki, kj);
    const int          offset = std::abs(int(kj) - int(ki));
    // The group of a (the last entry is the sentinel).
    const auto group = std::upper_bound(group_list.begin(),
                                        group_list.end() - 1,
                                        a,
                                        [](const unsigned int particle, const Group &g) {
                                          return particle < g.first_particle;
                                        }) -
                       1;
    for (unsigned int q = group->first_block; q < (group + 1)->first_block; ++q)
      {
        const std::size_t lane = std::size_t(q) * width + (a - group->first_particle);
        if (block_list[q].offset == offset && lane_bond[lane] == b)
          return lane;
      }
    Assert(false, ExcMessage("Bond " + std::to_string(b) + " is in no lane."));
    return numbers::invalid_unsigned_int;
  }

  template <int dim>
  void
  BondBlocks<dim>::lanes_of_bonds(const std::size_t n_bonds, std::vector<unsigned int> &lane) const
  {
    lane.assign(n_bonds, numbers::invalid_unsigned_int);
    for (std::size_t l = 0; l < lane_bond.size(); ++l)
      if (lane_bond[l] != numbers::invalid_unsigned_int)
        {
          AssertIndexRange(lane_bond[l], n_bonds);
          lane[lane_bond[l]] = l;
        }
  }

  template <int dim>
  void
  BondBlocks<dim>::from_lanes(const Array &per_lane, std::vector<double> &per_bond) const
  {
    for (std::size_t l = 0; l < lane_bond.size(); ++l)
      if (lane_bond[l] != numbers::invalid_unsigned_int)
        per_bond[lane_bond[l]] = per_lane[l];
  }

  template <int dim>
  void
  BondBlocks<dim>::sync_state(const BondList &bonds)
  {
    if (bonds.revision() == synced_revision)
      return;
    for (std::size_t l = 0; l < lane_bond.size(); ++l)
      lane_state[l] =
        (lane_bond[l] == numbers::invalid_unsigned_int ? 0 : bonds.intact[lane_bond[l]]);
    synced_revision = bonds.revision();
  }

  template <int dim>
  void
  BondBlocks<dim>::break_lanes(const bond_simd::Vector &stretch,
                               const double             critical_stretch,
                               const unsigned int       q,
                               BondList                &bonds)
  {
    std::uint8_t *state = lane_state.data() + std::size_t(q) * width;
    for (unsigned int l = 0; l < width; ++l)
      if (state[l] == 1 && stretch[l] > critical_stretch)
        {
          const unsigned int b = lane_bond[std::size_t(q) * width + l];
          state[l]             = 0;
          bonds.intact[b]      = 0;
          bonds.newly_broken.push_back(b);
        }
  }

  template <int dim>
  void
  BondBlocks<dim>::reinit_field(Array &field, const unsigned int n_components) const
  {
    field.resize_fast(field_stride * n_components);
    field.fill(0.);
  }

  template <int dim>
  double *
  BondBlocks<dim>::component(Array &field, const unsigned int d) const
  {
    return field.data() + std::size_t(d) * field_stride + width;
  }

  template <int dim>
  void
  BondBlocks<dim>::gather(const double *values, const unsigned int n_components, Array &field) const
  {
    double *target = component(field, 0);
    for (unsigned int i = 0; i < n_local; ++i)
      for (unsigned int d = 0; d < n_components; ++d)
        target[d * field_stride + kernel_index[i]] = values[std::size_t(i) * n_components + d];
  }

  template <int dim>
  void
  BondBlocks<dim>::scatter_owned(Array             &field,
                                 const unsigned int n_components,
                                 const double      *divisor,
                                 double            *values) const
  {
    const double *source = component(field, 0);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const double divide_by = (divisor != nullptr ? divisor[i] : 1.);
        for (unsigned int d = 0; d < n_components; ++d)
          values[std::size_t(i) * n_components + d] =
            source[d * field_stride + kernel_index[i]] / divide_by;
      }
  }

  template class BondBlocks<2>;
  template class BondBlocks<3>;
} // namespace perideal
