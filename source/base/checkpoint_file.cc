// ---------------------------------------------------------------------
// PeriDeal: the file format of a checkpoint (header, named sections, MPI-IO, end mark).
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <perideal/base/checkpoint_file.h>

#include <algorithm>
#include <array>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // The first and the last 16 bytes of a checkpoint; the begin mark names the format.
    constexpr std::size_t mark_size                  = 16;
    constexpr char        begin_mark[mark_size + 1]  = "PERIDEAL-CKPT-02";
    constexpr char        format_stem[mark_size - 1] = "PERIDEAL-CKPT-";
    constexpr char        end_mark[mark_size + 1]    = "PERIDEAL-CKPT-OK";
    // The header's line of a section.
    const std::string section_key = "section ";

    // Independent reads and writes at byte offsets, in pieces an int can count.
    void
    write_at(MPI_File            handle,
             const std::uint64_t offset,
             const void         *data,
             const std::uint64_t bytes)
    {
      const char *begin = static_cast<const char *>(data);
      for (std::uint64_t done = 0; done < bytes;)
        {
          const int piece = static_cast<int>(std::min<std::uint64_t>(bytes - done, 1u << 30));
          const int ierr  = MPI_File_write_at(handle,
                                             offset + done,
                                             begin + done,
                                             piece,
                                             MPI_BYTE,
                                             MPI_STATUS_IGNORE);
          AssertThrowMPI(ierr);
          done += piece;
        }
    }

    void
    read_at(MPI_File handle, const std::uint64_t offset, void *data, const std::uint64_t bytes)
    {
      char *begin = static_cast<char *>(data);
      for (std::uint64_t done = 0; done < bytes;)
        {
          const int piece = static_cast<int>(std::min<std::uint64_t>(bytes - done, 1u << 30));
          const int ierr  = MPI_File_read_at(handle,
                                            offset + done,
                                            begin + done,
                                            piece,
                                            MPI_BYTE,
                                            MPI_STATUS_IGNORE);
          AssertThrowMPI(ierr);
          done += piece;
        }
    }

    // The sum of @p value over the ranks before this one.
    std::uint64_t
    sum_before(const std::uint64_t value, const MPI_Comm comm)
    {
      std::uint64_t before = 0;
      const int     ierr   = MPI_Exscan(&value, &before, 1, MPI_UINT64_T, MPI_SUM, comm);
      AssertThrowMPI(ierr);
      return Utilities::MPI::this_mpi_process(comm) == 0 ? 0 : before;
    }
  } // namespace

  CheckpointWriter::CheckpointWriter(const MPI_Comm comm)
    : comm(comm)
  {}

  void
  CheckpointWriter::add_line(const std::string &key, const std::string &value)
  {
    lines += key + " = " + value + "\n";
  }

  void
  CheckpointWriter::add_records(const std::string                &name,
                                const std::uint64_t               n_records,
                                const std::uint64_t               width,
                                const std::vector<std::uint64_t> &indices,
                                std::vector<char>                 data)
  {
    Assert(data.size() == indices.size() * width, ExcInternalError());
    Section section;
    section.name      = name;
    section.records   = true;
    section.n_records = n_records;
    section.width     = width;
    section.indices   = indices;
    section.data      = std::move(data);
    sections.push_back(std::move(section));
  }

  void
  CheckpointWriter::add_totals(const std::string &name, const std::vector<double> &totals)
  {
    const bool        root = Utilities::MPI::this_mpi_process(comm) == 0;
    std::vector<char> data;
    if (root)
      append_bytes(data, totals.data(), totals.size());
    add_records(name,
                1,
                totals.size() * sizeof(double),
                root ? std::vector<std::uint64_t>{0} : std::vector<std::uint64_t>{},
                std::move(data));
  }

  void
  CheckpointWriter::add_bytes(const std::string &name, std::vector<char> data)
  {
    Section section;
    section.name = name;
    section.data = std::move(data);
    sections.push_back(std::move(section));
  }

  void
  CheckpointWriter::write(const std::string &file) const
  {
    // The header: the lines, then each section's size (the same on every rank).
    std::string                header = lines;
    std::vector<std::uint64_t> bytes(sections.size()), before(sections.size());
    for (unsigned int s = 0; s < sections.size(); ++s)
      {
        const Section &section = sections[s];
        if (section.records)
          {
            bytes[s] = section.n_records * section.width;
            header += section_key + section.name + " = records " +
                      std::to_string(section.n_records) + " " + std::to_string(section.width) +
                      "\n";
          }
        else
          {
            bytes[s]  = Utilities::MPI::sum<std::uint64_t>(section.data.size(), comm);
            before[s] = sum_before(section.data.size(), comm);
            header += section_key + section.name + " = bytes " + std::to_string(bytes[s]) + "\n";
          }
      }
    const std::uint64_t header_bytes = header.size();
    std::uint64_t       offset       = mark_size + sizeof(header_bytes) + header_bytes;

    MPI_File handle;
    int      ierr =
      MPI_File_open(comm, file.c_str(), MPI_MODE_CREATE | MPI_MODE_WRONLY, MPI_INFO_NULL, &handle);
    AssertThrow(ierr == MPI_SUCCESS,
                ExcMessage("The checkpoint <" + file +
                           "> cannot be written (<Output/Directory>)."));
    std::uint64_t size = offset + mark_size;
    for (const auto b : bytes)
      size += b;
    ierr = MPI_File_set_size(handle, size);
    AssertThrowMPI(ierr);
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
    if (root)
      {
        write_at(handle, 0, begin_mark, mark_size);
        write_at(handle, mark_size, &header_bytes, sizeof(header_bytes));
        write_at(handle, mark_size + sizeof(header_bytes), header.data(), header_bytes);
        write_at(handle, size - mark_size, end_mark, mark_size);
      }
    for (unsigned int s = 0; s < sections.size(); ++s)
      {
        const Section &section = sections[s];
        if (section.records)
          // Contiguous runs of indices in one write each.
          for (std::size_t r = 0; r < section.indices.size();)
            {
              std::size_t end = r + 1;
              while (end < section.indices.size() &&
                     section.indices[end] == section.indices[end - 1] + 1)
                ++end;
              write_at(handle,
                       offset + section.indices[r] * section.width,
                       &section.data[r * section.width],
                       (end - r) * section.width);
              r = end;
            }
        else
          write_at(handle, offset + before[s], section.data.data(), section.data.size());
        offset += bytes[s];
      }
    ierr = MPI_File_sync(handle);
    AssertThrowMPI(ierr);
    ierr = MPI_File_close(&handle);
    AssertThrowMPI(ierr);
  }

  CheckpointReader::CheckpointReader(const MPI_Comm     comm,
                                     const std::string &file,
                                     const std::string &advice)
    : file(file)
    , advice(advice)
  {
    const std::string name = description();
    int ierr = MPI_File_open(comm, file.c_str(), MPI_MODE_RDONLY, MPI_INFO_NULL, &handle);
    AssertThrow(ierr == MPI_SUCCESS, ExcMessage(name + " cannot be opened" + advice));
    MPI_Offset size = 0;
    ierr            = MPI_File_get_size(handle, &size);
    AssertThrowMPI(ierr);
    const auto damaged = [&](const std::string &what) {
      MPI_File_close(&handle);
      return ExcMessage(name + " is " + what +
                        "; restart from a complete checkpoint, or start the run again without "
                        "--restart. Nothing was written.");
    };
    std::array<char, mark_size> mark{};
    std::uint64_t               header_bytes = 0;
    AssertThrow(std::uint64_t(size) >= 2 * mark_size + sizeof(header_bytes),
                damaged("truncated (" + std::to_string(size) + " bytes)"));
    read_at(handle, 0, mark.data(), mark_size);
    const std::string found(mark.data(), mark_size);
    AssertThrow(found.rfind(format_stem, 0) != 0 || found == begin_mark,
                damaged("of another format (it starts with " + found + ", this version reads " +
                        begin_mark + "; a checkpoint is read by the version that wrote it)"));
    AssertThrow(found == begin_mark,
                damaged("not a PeriDeal checkpoint (it does not start with " +
                        std::string(begin_mark) + ")"));
    read_at(handle, mark_size, &header_bytes, sizeof(header_bytes));
    AssertThrow(mark_size + sizeof(header_bytes) + header_bytes + mark_size <= std::uint64_t(size),
                damaged("truncated (" + std::to_string(size) + " bytes, shorter than its header)"));
    std::string header_text(header_bytes, '\0');
    read_at(handle, mark_size + sizeof(header_bytes), header_text.data(), header_bytes);

    // The lines, and the sections in their order.
    std::uint64_t      offset = mark_size + sizeof(header_bytes) + header_bytes;
    std::istringstream in(header_text);
    for (std::string line; std::getline(in, line);)
      {
        const auto equal = line.find(" = ");
        if (equal == std::string::npos)
          continue;
        const std::string key = line.substr(0, equal), value = line.substr(equal + 3);
        lines[key] = value;
        if (key.rfind(section_key, 0) != 0)
          continue;
        std::istringstream fields(value);
        std::string        kind;
        Section            section;
        fields >> kind;
        if (kind == "records")
          {
            fields >> section.n_records >> section.width;
            section.bytes = section.n_records * section.width;
          }
        else
          {
            fields >> section.bytes;
            section.n_records = section.bytes;
            section.width     = 1;
          }
        AssertThrow(!fields.fail() && (kind == "records" || kind == "bytes"),
                    damaged("damaged (its header line <" + line + ">)"));
        section.offset                           = offset;
        sections[key.substr(section_key.size())] = section;
        offset += section.bytes;
      }
    AssertThrow(std::uint64_t(size) == offset + mark_size,
                damaged("truncated or damaged (" + std::to_string(size) + " bytes, its header " +
                        "gives " + std::to_string(offset + mark_size) + ")"));
    read_at(handle, offset, mark.data(), mark_size);
    AssertThrow(std::memcmp(mark.data(), end_mark, mark_size) == 0,
                damaged("damaged (it does not end with " + std::string(end_mark) + ")"));
  }

  CheckpointReader::~CheckpointReader()
  {
    MPI_File_close(&handle);
  }

  const std::map<std::string, std::string> &
  CheckpointReader::header() const
  {
    return lines;
  }

  std::uint64_t
  CheckpointReader::number(const std::string &key) const
  {
    const auto found = lines.find(key);
    AssertThrow(found != lines.end(),
                ExcMessage(description() + " is damaged (no <" + key +
                           "> in its header). Nothing was written."));
    return std::stoull(found->second);
  }

  bool
  CheckpointReader::has_section(const std::string &name) const
  {
    return sections.find(name) != sections.end();
  }

  const CheckpointReader::Section &
  CheckpointReader::section(const std::string &name) const
  {
    const auto found = sections.find(name);
    AssertThrow(found != sections.end(),
                ExcMessage(description() + " has no section <" + name +
                           ">: it is from another problem. Nothing was written."));
    return found->second;
  }

  std::uint64_t
  CheckpointReader::n_records(const std::string &name) const
  {
    return section(name).n_records;
  }

  std::vector<char>
  CheckpointReader::read_records(const std::string                &name,
                                 const std::uint64_t               width,
                                 const std::vector<std::uint64_t> &indices)
  {
    const Section &records = section(name);
    AssertThrow(records.width == width && (indices.empty() || indices.back() < records.n_records),
                ExcMessage(description() + " is from another problem: its section <" + name +
                           "> has " + std::to_string(records.n_records) + " records of " +
                           std::to_string(records.width) + " bytes, this run reads records of " +
                           std::to_string(width) + " bytes. Nothing was written."));
    std::vector<char> data(indices.size() * width);
    for (std::size_t r = 0; r < indices.size();)
      {
        std::size_t end = r + 1;
        while (end < indices.size() && indices[end] == indices[end - 1] + 1)
          ++end;
        read_at(handle, records.offset + indices[r] * width, &data[r * width], (end - r) * width);
        r = end;
      }
    return data;
  }

  std::vector<double>
  CheckpointReader::read_totals(const std::string &name, const std::size_t n)
  {
    const std::vector<char> data = read_records(name, n * sizeof(double), {0});
    std::vector<double>     totals(n);
    std::memcpy(totals.data(), data.data(), data.size());
    return totals;
  }

  std::vector<char>
  CheckpointReader::read_all(const std::string &name)
  {
    const Section    &all = section(name);
    std::vector<char> data(all.bytes);
    read_at(handle, all.offset, data.data(), all.bytes);
    return data;
  }

  std::string
  CheckpointReader::description() const
  {
    return "The checkpoint <" + file + ">";
  }
} // namespace perideal
