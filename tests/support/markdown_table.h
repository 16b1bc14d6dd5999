// The rows of the first Markdown table after a heading of a page under docs/, cell by cell:
// for tests that hold a table in the docs to the one definition in code (the run schema, the
// check table). A cell's `code` backticks are removed and "\|" (a | inside a cell) is read as "|".
#pragma once

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace collide::test {

inline std::string read_source_file(const std::string& relative) {
    const std::string path = std::string(COLLIDE_SOURCE_DIR) + "/" + relative;
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot read");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline std::vector<std::string> table_cells(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    for (std::size_t i = 1; i < line.size(); ++i) {  // line[0] is the opening '|'
        if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
            cell += '|';
            ++i;
        } else if (line[i] == '|') {
            const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
            cell = first == std::string::npos ? "" : cell.substr(first, last - first + 1);
            if (cell.size() >= 2 && cell.front() == '`' && cell.back() == '`' &&
                cell.find('`', 1) == cell.size() - 1)
                cell = cell.substr(1, cell.size() - 2);
            cells.push_back(cell);
            cell.clear();
        } else {
            cell += line[i];
        }
    }
    return cells;
}

// The body rows (without the header and the --- line) of the first table after `heading`.
inline std::vector<std::vector<std::string>> markdown_table_after(const std::string& page, const std::string& heading) {
    const std::string text = read_source_file(page);
    const auto at = text.find("\n" + heading + "\n");
    if (at == std::string::npos) throw std::runtime_error(page + ": no heading '" + heading + "'");
    std::vector<std::vector<std::string>> rows;
    std::size_t pos = text.find("\n|", at);
    bool header = true;
    while (pos != std::string::npos && pos + 1 < text.size() && text[pos + 1] == '|') {
        const std::size_t end = text.find('\n', pos + 1);
        const std::string line = text.substr(pos + 1, end - pos - 1);
        if (header) header = false;
        else if (line.rfind("| ---", 0) != 0) rows.push_back(table_cells(line));
        pos = end;
    }
    return rows;
}

}  // namespace collide::test
