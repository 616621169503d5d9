#pragma once
// The labeler's keys, in one place: what the window shows and what --answers files contain.
#include <string>

namespace rdsf::label_keys {

constexpr char kPerson = 'y';
constexpr char kNotPerson = 'n';
constexpr char kSkip = 's';
constexpr char kUndo = 'u';
constexpr char kQuit = 'q';
constexpr char kZoomIn = '+';   ///< the frame, around the candidate (window only; ignored in --answers)
constexpr char kZoomOut = '-';
constexpr char kNone = '\0';

/// The legend shown on screen.
inline const char* legend() {
  return "[y] person   [n] not a person   [s/space] skip   [u/backspace] undo   [+/-] zoom   [q/Esc] save and quit";
}

/// Maps a highgui key code (cv::waitKeyEx) to a key above; kNone for anything else.
inline char from_key_code(int code) {
  if (code < 0) return kNone;
  switch (code) {
    case 'y': case 'Y': return kPerson;
    case 'n': case 'N': return kNotPerson;
    case 's': case 'S': case ' ': return kSkip;
    case 'u': case 'U': case 8: case 127: case 0xff08: case 0x10000 + 8: return kUndo;  // backspace variants
    case 'q': case 'Q': case 27: return kQuit;
    case '+': case '=': case 0xffab: return kZoomIn;   // = is + without shift; 0xffab keypad +
    case '-': case 0xffad: return kZoomOut;
    default: return kNone;
  }
}

/// Maps a token of an --answers file: a single key letter, "space", "backspace" or "esc".
inline char from_token(const std::string& token) {
  if (token == "space") return kSkip;
  if (token == "backspace") return kUndo;
  if (token == "esc") return kQuit;
  if (token.size() == 1) return from_key_code(static_cast<unsigned char>(token[0]));
  return kNone;
}

}  // namespace rdsf::label_keys
