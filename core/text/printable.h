// Text that collide did not write (an outside solver's output, a key or a name read from a
// file, a value given on the command line), made safe to print on a terminal or in a message:
// every control character and every byte that is not part of well-formed UTF-8 is shown as
// \xNN (letters of any script pass). A terminal escape (ESC, 0x1b) then
// cannot move the cursor or recolour the screen, a line break cannot forge a line of collide's
// own summary ("FAIL ...", "checks 10 passed"), and invalid UTF-8 cannot garble what follows.
// The one sanitiser of the C++ side; validation/report/printable.py is its Python twin (and
// escapes Markdown and HTML for the report's pages).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace collide {

enum class LineBreaks { escaped, kept };

// `text` with every control character (C0, DEL, C1) and every byte of ill-formed UTF-8 shown
// as \xNN (a backslash itself stays as it is);
// LineBreaks::kept lets '\n' through, for a block quoted on lines of its own.
std::string printable(std::string_view text, LineBreaks line_breaks = LineBreaks::escaped);

// printable() of at most the last `max_chars` bytes of `text`, after "..." when cut.
std::string printable_tail(std::string_view text, std::size_t max_chars, LineBreaks line_breaks = LineBreaks::escaped);

// Whether `text` holds a control character (a byte below 0x20, or 0x7f): such text cannot be
// one line of a key, a path or a value, and is refused where it is read.
bool has_control_character(std::string_view text);

}  // namespace collide
