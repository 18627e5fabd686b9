// The one CSV reader and writer of towdb. Two dialects of reading:
//  * plain: a comma always separates cells, nothing is quoted -- the files
//    towdb writes and reads back itself (the validation journal, the
//    calibration tables), whose cells never hold a comma;
//  * quoted (RFC 4180 cells): a cell in double quotes may hold commas, a
//    doubled quote stands for one quote; carriage returns outside quotes are
//    dropped and every cell is trimmed of spaces -- input typed or exported by
//    people (`towdb query --batch`).
// Writing: cell() quotes a cell only when it must (a comma, quote or newline).
#ifndef TOWDB_IO_CSV_HPP
#define TOWDB_IO_CSV_HPP

#include <string>
#include <string_view>
#include <vector>

namespace towdb::io::csv {

// The cells of one line split at every comma (n commas give n + 1 cells).
std::vector<std::string> split_plain(std::string_view line);

// The cells of one line in the quoted dialect; *unterminated is set when a
// quoted cell has no closing quote (the line cannot be read as the writer
// meant it).
std::vector<std::string> split_quoted(std::string_view line, bool* unterminated);

// `text` as one CSV cell: unchanged, or in double quotes with every quote
// doubled when it holds a comma, a quote or a newline.
std::string cell(const std::string& text);

}  // namespace towdb::io::csv

#endif  // TOWDB_IO_CSV_HPP
