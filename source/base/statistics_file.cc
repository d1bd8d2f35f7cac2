#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/statistics_file.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace perideal
{
  StatisticsFile::StatisticsFile(MPI_Comm comm, const std::string &filename)
    : filename(filename)
    , is_root(dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    , header_written(false)
  {
    AssertThrow(!filename.empty(),
                dealii::ExcMessage("The statistics file name must not be empty."));
  }



  void
  StatisticsFile::add_value(const std::string &name, const double value)
  {
    const std::string column = column_prefix + name;
    if (std::find(columns.begin(), columns.end(), column) == columns.end())
      {
        AssertThrow(!column.empty() && column.find_first_of(",\"\n\r") == std::string::npos,
                    dealii::ExcMessage("The statistics column name <" + column +
                                       "> must be non-empty and must not "
                                       "contain commas, quotes or newlines."));
        AssertThrow(!header_written,
                    dealii::ExcMessage("The statistics column <" + column +
                                       "> appeared after the header of <" + filename +
                                       "> was written; all columns must receive a value "
                                       "before the first end_row()."));
        columns.push_back(column);
      }
    current_row[column] = value;
  }



  void
  StatisticsFile::set_column_prefix(const std::string &prefix)
  {
    column_prefix = prefix;
  }

  void
  StatisticsFile::end_row()
  {
    if (is_root)
      {
        if (!file.is_open())
          {
            file.open(filename, std::ios::out | std::ios::trunc);
            AssertThrow(file, dealii::ExcFileNotOpen(filename));
          }

        std::ostringstream line;
        if (!header_written)
          {
            for (unsigned int c = 0; c < columns.size(); ++c)
              line << (c > 0 ? "," : "") << columns[c];
            line << '\n';
          }

        line << std::scientific << std::setprecision(9);
        for (unsigned int c = 0; c < columns.size(); ++c)
          {
            if (c > 0)
              line << ',';
            const auto value = current_row.find(columns[c]);
            if (value != current_row.end())
              line << value->second;
          }
        line << '\n';

        file << line.str();
        file.flush();
        AssertThrow(file,
                    dealii::ExcMessage("Writing to the statistics file <" + filename +
                                       "> failed."));
      }

    header_written = true;
    current_row.clear();
  }



  void
  StatisticsFile::resume(const std::string &contents)
  {
    AssertThrow(!header_written,
                dealii::ExcMessage("The statistics file <" + filename +
                                   "> can only be resumed before its first row."));
    const std::string header = contents.substr(0, contents.find('\n'));
    columns                  = dealii::Utilities::split_string_list(header, ',');
    header_written           = !contents.empty();
    if (is_root)
      {
        file.open(filename, std::ios::out | std::ios::trunc);
        AssertThrow(file, dealii::ExcFileNotOpen(filename));
        file << contents;
        file.flush();
        AssertThrow(file,
                    dealii::ExcMessage("Writing to the statistics file <" + filename +
                                       "> failed."));
      }
  }



  std::string
  StatisticsFile::contents() const
  {
    if (!is_root || !header_written)
      return {};
    std::ifstream      in(filename);
    std::ostringstream text;
    text << in.rdbuf();
    AssertThrow(in, dealii::ExcMessage("Reading the statistics file <" + filename + "> failed."));
    return text.str();
  }



  const std::string &
  StatisticsFile::get_filename() const
  {
    return filename;
  }

  void
  print_without_round_off(std::ostream              &out,
                          const std::vector<double> &values,
                          const double               accuracy)
  {
    double norm = 0.;
    for (const double value : values)
      norm += value * value;
    const double below = std::max(1e-10 * std::sqrt(norm), accuracy);
    for (unsigned int k = 0; k < values.size(); ++k)
      out << (k > 0 ? " " : "")
          << (std::abs(values[k]) < below ? 0. : to_accuracy(values[k], accuracy));
  }
} // namespace perideal
