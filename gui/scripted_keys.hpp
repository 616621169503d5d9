#pragma once
// Keys from a file or stdin instead of a window (the programs' headless mode, --answers / --keys), read as
// they are needed, so that keys typed or piped in one by one are handled one by one: whitespace-separated
// tokens; a token the program names (e.g. "space", "pagedown") is one key, any other token is one key per
// letter ("yyn" is three). An unknown key is an Error naming the file (or "standard input") and the keys.
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace rdsf::gui {

class ScriptedKeys {
 public:
  /// `named` maps a whole token to a key ('\0' when it names none), `letter` one character ('\0' unknown);
  /// `known` lists the keys for the error message ("y n s u q").
  ScriptedKeys(const std::string& path, std::function<char(const std::string&)> named,
               std::function<char(char)> letter, std::string known);
  /// The next key; false when the keys ran out.
  bool next(char& key);

 private:
  std::istream& in();
  std::string path_;
  std::ifstream file_;
  std::function<char(const std::string&)> named_;
  std::function<char(char)> letter_;
  std::string known_;
  std::vector<char> pending_;
};

}  // namespace rdsf::gui
