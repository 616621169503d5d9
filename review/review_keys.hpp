#pragma once
// The review's keys, in one place: what the window shows and what --keys files contain.
#include <string>

namespace rdsf::review_keys {

constexpr char kFlip = 'f';
constexpr char kRetract = 'x';
constexpr char kOpenFrame = 'o';
constexpr char kNext = 'l';      ///< next sample (right arrow)
constexpr char kPrevious = 'h';  ///< previous sample (left arrow)
constexpr char kDown = 'j';      ///< one row down
constexpr char kUp = 'k';        ///< one row up
constexpr char kNextPage = 'n';  ///< page down, space
constexpr char kPreviousPage = 'p';  ///< page up, b
constexpr char kQuit = 'q';
constexpr char kNone = '\0';

inline const char* legend() {
  return "[f] flip label   [x/Del] retract   [o] open frame   [arrows/hjkl] move   [n/space/PgDn] [p/b/PgUp] page   [q/Esc] quit";
}

/// Maps a highgui key code (cv::waitKeyEx) to a key above; kNone for anything else.
inline char from_key_code(int code) {
  switch (code) {
    case 'f': case 'F': return kFlip;
    case 'x': case 'X': case 0xffff: case 127: return kRetract;  // Delete
    case 'o': case 'O': return kOpenFrame;
    case 'l': case 0xff53: case 0x270000: return kNext;          // right arrow (X11, Qt)
    case 'h': case 0xff51: case 0x250000: return kPrevious;      // left arrow
    case 'j': case 0xff54: case 0x280000: return kDown;          // down arrow
    case 'k': case 0xff52: case 0x260000: return kUp;            // up arrow
    case 'n': case ' ': case 0xff56: case 0x220000: return kNextPage;
    case 'p': case 'b': case 0xff55: case 0x210000: return kPreviousPage;
    case 'q': case 'Q': case 27: return kQuit;
    default: return kNone;
  }
}

/// A whole token of a --keys file: right, left, down, up, space, pagedown, pageup, delete, esc.
inline char from_token(const std::string& t) {
  if (t == "right") return kNext;
  if (t == "left") return kPrevious;
  if (t == "down") return kDown;
  if (t == "up") return kUp;
  if (t == "space" || t == "pagedown") return kNextPage;
  if (t == "pageup") return kPreviousPage;
  if (t == "delete") return kRetract;
  if (t == "esc") return kQuit;
  return kNone;
}

}  // namespace rdsf::review_keys
