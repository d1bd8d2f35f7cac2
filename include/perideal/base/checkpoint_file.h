// ---------------------------------------------------------------------
// PeriDeal: the file format of a checkpoint (header, named sections, MPI-IO, end mark).
// ---------------------------------------------------------------------
#ifndef perideal_base_checkpoint_file_h
#define perideal_base_checkpoint_file_h

#include <deal.II/base/mpi.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief The sections of a checkpoint, collected on every rank and written collectively as one
   * file (doc/architecture/09_checkpoints.md). The file is: a begin mark, the size of the
   * header, the header ("key = value" lines: the caller's lines, then one line per section with
   * its size), the sections in the order they were added, and an end mark. Two kinds of section:
   *
   * - records: a fixed number of records of a fixed width, each written by one rank at its
   *   index (the particles' records at their ParticleSystem::invariant_index(), a rank's sums
   *   at its rank), so that another rank count reads them at other indices;
   * - bytes: each rank's bytes, concatenated in rank order (broken bonds, FE cells, the
   *   postprocessors' state of rank 0); every rank reads the whole section.
   *
   * The writers of the sections are the regions themselves (ParticleRegion, FERegion,
   * CoupledState), which own what they store; this class knows only the format.
   */
  class CheckpointWriter
  {
  public:
    /// A checkpoint written by the ranks of @p comm.
    explicit CheckpointWriter(const MPI_Comm comm);

    /// A line "@p key = @p value" of the header (the same on every rank).
    void
    add_line(const std::string &key, const std::string &value);

    /**
     * @brief The section @p name of @p n_records records of @p width bytes (the same on every
     * rank): this rank writes @p data, record r at index @p indices[r] (in increasing order).
     */
    void
    add_records(const std::string                &name,
                const std::uint64_t               n_records,
                const std::uint64_t               width,
                const std::vector<std::uint64_t> &indices,
                std::vector<char>                 data);

    /**
     * @brief The section @p name of one record, @p totals written by rank 0 (values the same on
     * every rank, or rank 0's totals of sums over the ranks): CheckpointReader::read_totals()
     * gives them to every rank.
     */
    void
    add_totals(const std::string &name, const std::vector<double> &totals);

    /// The section @p name: this rank's @p data (may be empty), in rank order.
    void
    add_bytes(const std::string &name, std::vector<char> data);

    /**
     * @brief Write the file @p file (created or replaced, not renamed: Checkpoint writes a
     * temporary name and renames it). Collective.
     */
    void
    write(const std::string &file) const;

  private:
    struct Section
    {
      std::string                name;
      bool                       records   = false;
      std::uint64_t              n_records = 0, width = 0;
      std::vector<std::uint64_t> indices;
      std::vector<char>          data;
    };

    MPI_Comm             comm;
    std::string          lines;
    std::vector<Section> sections;
  };

  /**
   * @brief A checkpoint file opened for reading (CheckpointWriter's format): the marks and the
   * size are checked when it opens, each failure naming the file; sections are read by name.
   * Collective functions: every rank calls them in the same order.
   */
  class CheckpointReader
  {
  public:
    /**
     * @brief Open @p file and check that it is a complete checkpoint of this format (its marks
     * and its size against its header); otherwise stop with a message naming the file and
     * @p advice (what to do instead). Collective.
     */
    CheckpointReader(const MPI_Comm comm, const std::string &file, const std::string &advice);

    ~CheckpointReader();

    CheckpointReader(const CheckpointReader &) = delete;
    CheckpointReader &
    operator=(const CheckpointReader &) = delete;

    /// The header's lines "key = value" (the sections' lines too).
    const std::map<std::string, std::string> &
    header() const;

    /// The header's value of @p key as a number (stops naming the key if it is missing).
    std::uint64_t
    number(const std::string &key) const;

    /// Whether the file has the section @p name.
    bool
    has_section(const std::string &name) const;

    /// The number of records of the records section @p name (the size in bytes of a bytes one).
    std::uint64_t
    n_records(const std::string &name) const;

    /**
     * @brief The records at @p indices (increasing) of the records section @p name, each of
     * @p width bytes (checked against the file), one after the other. Not collective.
     */
    std::vector<char>
    read_records(const std::string                &name,
                 const std::uint64_t               width,
                 const std::vector<std::uint64_t> &indices);

    /**
     * @brief The @p n values that CheckpointWriter::add_totals() wrote into the section @p name
     * (checked against the file), on every rank. Not collective.
     */
    std::vector<double>
    read_totals(const std::string &name, const std::size_t n);

    /// The whole section @p name (of either kind). Not collective.
    std::vector<char>
    read_all(const std::string &name);

    /// "The checkpoint <file>", for the messages of the readers of the sections.
    std::string
    description() const;

  private:
    struct Section
    {
      std::uint64_t offset = 0, bytes = 0, n_records = 0, width = 0;
    };

    const Section &
    section(const std::string &name) const;

    std::string                        file;
    std::string                        advice;
    MPI_File                           handle;
    std::map<std::string, std::string> lines;
    std::map<std::string, Section>     sections;
  };

  /// Append the bytes of @p value to @p data.
  template <typename T>
  void
  append_bytes(std::vector<char> &data, const T *value, const std::size_t n = 1)
  {
    const char *begin = reinterpret_cast<const char *>(value);
    data.insert(data.end(), begin, begin + n * sizeof(T));
  }

  /// Read @p n values of type T from @p position, advancing it.
  template <typename T>
  void
  take_bytes(const char *&position, T *value, const std::size_t n = 1)
  {
    std::memcpy(value, position, n * sizeof(T));
    position += n * sizeof(T);
  }
} // namespace perideal

#endif
