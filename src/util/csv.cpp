#include "util/csv.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "util/input_file.h"

namespace mirage {

int CsvTable::column(std::string_view name) const {
    for (size_t i = 0; i < header.size(); ++i)
        if (header[i] == name) return static_cast<int>(i);
    return -1;
}

std::string CsvTable::where(const CsvRow& row, int column) const {
    const FileLoc at = static_cast<std::size_t>(column) < row.places.size()
                           ? row.places[static_cast<std::size_t>(column)]
                           : FileLoc{source, row.line, 0};
    return to_string(at) + ": column '" + header.at(static_cast<std::size_t>(column)) + "'";
}

Result<CsvTable> parse_csv(std::string_view text, const std::string& source) {
    // Spreadsheets often begin a UTF-8 file with a byte-order mark: not part of the header.
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    CsvTable table;
    table.source = source;
    std::vector<CsvRow> rows;
    CsvRow row;
    std::string field;
    int line = 1;
    row.line = 1;
    std::size_t line_start = 0;  // offset of the current line's first byte
    FileLoc field_place{source, 1, 1};
    bool in_quotes = false;
    bool row_has_content = false;
    auto end_field = [&] {
        row.fields.push_back(field);
        row.places.push_back(field_place);
        field.clear();
    };
    auto end_row = [&] {
        end_field();
        if (row_has_content || row.fields.size() > 1 || !row.fields[0].empty())
            rows.push_back(std::move(row));
        row = CsvRow{};
        row_has_content = false;
    };
    for (size_t i = 0; i < text.size(); ++i) {
        const char ch = text[i];
        if (in_quotes) {
            if (ch == '"') {
                if (i + 1 < text.size() && text[i + 1] == '"') {
                    field += '"';
                    ++i;
                } else {
                    in_quotes = false;
                }
            } else {
                if (ch == '\n' || (ch == '\r' && !(i + 1 < text.size() && text[i + 1] == '\n'))) {
                    ++line;
                    line_start = i + 1;
                }
                field += ch;
            }
            continue;
        }
        if (ch == '"') {
            in_quotes = true;
            row_has_content = true;
        } else if (ch == ',') {
            end_field();
            field_place = FileLoc{source, line, static_cast<int>(i + 1 - line_start) + 1};
            row_has_content = true;
        } else if (ch == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
            // CRLF: the '\n' ends the line
        } else if (ch == '\n' || ch == '\r') {
            // A lone CR ends a line too (old Mac files).
            end_row();
            ++line;
            line_start = i + 1;
            row.line = line;
            field_place = FileLoc{source, line, 1};
        } else {
            field += ch;
            row_has_content = true;
        }
    }
    if (in_quotes)
        return make_error(source + ":" + std::to_string(row.line) + ": unterminated quoted field");
    if (row_has_content || !field.empty()) end_row();
    if (rows.empty()) return make_error(source + ": empty CSV (no header row)");
    table.header = std::move(rows.front().fields);
    for (size_t r = 1; r < rows.size(); ++r) {
        if (rows[r].fields.size() != table.header.size()) {
            return make_error(source + ":" + std::to_string(rows[r].line) + ": row has " +
                              std::to_string(rows[r].fields.size()) + " fields, the header has " +
                              std::to_string(table.header.size()));
        }
        table.rows.push_back(std::move(rows[r]));
    }
    return table;
}

Result<CsvTable> read_csv_file(const std::string& path) {
    auto text = read_input_file(path, InputKind{"a CSV table", "CSV tables", kMaxCsvBytes});
    if (!text) return text.error();
    return parse_csv(*text, path);
}

Result<double> csv_number(const CsvTable& table, const CsvRow& row, int column) {
    const std::string& text = row.fields.at(column);
    const std::string where = table.where(row, column);
    if (text.empty()) return make_error(where + ": missing number");
    if (text.find_first_of("xX") != std::string::npos)
        return make_error(where + ": '" + quote_cut(text) + "' is not a decimal number");
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size())
        return make_error(where + ": '" + quote_cut(text) + "' is not a number");
    // strtod sets ERANGE for an overflow (and for an underflow, which loses only digits).
    if (errno == ERANGE && std::isinf(v))
        return make_error(where + ": '" + quote_cut(text) + "' is out of the range of a double");
    return v;
}

}  // namespace mirage
