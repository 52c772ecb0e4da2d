// A small CSV reader (RFC 4180: quoted fields, doubled quotes) that keeps each row's line
// number, so that errors can name the row and the column.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "util/file_loc.h"
#include "util/result.h"

namespace mirage {

struct CsvRow {
    int line = 0;  // 1-based line of the file where the row starts
    std::vector<std::string> fields;
    std::vector<FileLoc> places;  // where each field starts (its opening quote, if quoted)
};

struct CsvTable {
    std::string source;  // file name, for messages
    std::vector<std::string> header;
    std::vector<CsvRow> rows;

    /// Index of the named column, or -1.
    int column(std::string_view name) const;

    /// Where the field of `row` in `column` starts, and "file:line:column: column 'name'"
    /// for a message about it.
    std::string where(const CsvRow& row, int column) const;
};

/// Parses CSV text whose first row is the header; lines end at LF, CRLF or a lone CR.  Rows with
/// another field count than the header, unterminated quotes and an empty text are errors naming
/// source:line.  A UTF-8 byte-order mark at the start is skipped.
Result<CsvTable> parse_csv(std::string_view text, const std::string& source);

/// The largest CSV file read, bytes (a million rows of ten columns fit in it).
constexpr std::size_t kMaxCsvBytes = std::size_t{64} << 20;

/// Reads and parses a CSV file: a regular file of at most kMaxCsvBytes (read_input_file).
Result<CsvTable> read_csv_file(const std::string& path);

/// Parses a whole field as a decimal double ("nan" and "inf" as written are accepted); hex
/// floats and numbers out of the range of a double (1e999) are errors naming the place.
Result<double> csv_number(const CsvTable& table, const CsvRow& row, int column);

}  // namespace mirage
