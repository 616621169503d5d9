#include "support/crash_replay.hpp"

#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include <fcntl.h>

#include "rdsf/core/error.hpp"

namespace rdsf::test {

namespace fs = std::filesystem;

std::vector<RecordedCall> read_io_record(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be opened");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<RecordedCall> calls;
  std::size_t at = 0;
  auto take = [&](void* out, std::size_t size) {
    if (at + size > bytes.size()) fail(path, "record cut short at byte " + std::to_string(at));
    std::memcpy(out, bytes.data() + at, size);
    at += size;
  };
  auto take_text = [&](std::string& out) {
    std::uint64_t size = 0;
    take(&size, sizeof size);
    if (at + size > bytes.size()) fail(path, "record cut short at byte " + std::to_string(at));
    out.assign(bytes.data() + at, size);
    at += size;
  };
  while (at < bytes.size()) {
    RecordedCall c;
    std::uint8_t kind = 0;
    take(&kind, 1);
    c.call = static_cast<io::Call>(kind);
    take(&c.fd, sizeof c.fd);
    take(&c.value, sizeof c.value);
    take_text(c.path);
    take_text(c.path2);
    take_text(c.data);
    calls.push_back(std::move(c));
  }
  return calls;
}

namespace {

struct Inode {
  std::string live, synced;
  bool folder = false;
};

struct Model {
  std::vector<Inode> inodes;
  std::map<std::string, std::size_t> live_names, synced_names;  ///< path -> inode
  struct Open {
    std::size_t inode;
    std::string path;
  };
  std::map<int, Open> fds;

  std::size_t add(bool folder) {
    inodes.push_back({});
    inodes.back().folder = folder;
    return inodes.size() - 1;
  }

  static std::string parent(const std::string& path) { return fs::path(path).parent_path().string(); }

  void apply(const RecordedCall& c) {
    switch (c.call) {
      case io::Call::open: {
        auto found = live_names.find(c.path);
        std::size_t inode;
        if (found != live_names.end()) {
          inode = found->second;
        } else {
          // Created now, or a file made before the record (an input): known with unknown synced bytes.
          inode = add((c.value & O_DIRECTORY) != 0);
          if ((c.value & O_CREAT) != 0) live_names[c.path] = inode;
        }
        if ((c.value & O_TRUNC) != 0) inodes[inode].live.clear();
        fds[c.fd] = {inode, c.path};
        break;
      }
      case io::Call::write: {
        std::string& data = inodes[fds.at(c.fd).inode].live;
        const std::size_t end = static_cast<std::size_t>(c.value) + c.data.size();
        if (data.size() < end) data.resize(end, '\0');
        data.replace(static_cast<std::size_t>(c.value), c.data.size(), c.data);
        break;
      }
      case io::Call::truncate: inodes[fds.at(c.fd).inode].live.resize(static_cast<std::size_t>(c.value)); break;
      case io::Call::fdatasync:
      case io::Call::fsync: {
        const Open& o = fds.at(c.fd);
        Inode& inode = inodes[o.inode];
        if (!inode.folder) {
          inode.synced = inode.live;
          break;
        }
        // A folder: its names reach the disk as they are now.
        for (auto it = synced_names.begin(); it != synced_names.end();) {
          it = parent(it->first) == o.path ? synced_names.erase(it) : std::next(it);
        }
        for (const auto& [name, node] : live_names) {
          if (parent(name) == o.path) synced_names[name] = node;
        }
        break;
      }
      case io::Call::rename:
        live_names[c.path2] = live_names.at(c.path);
        live_names.erase(c.path);
        break;
      case io::Call::link: live_names[c.path2] = live_names.at(c.path); break;
      case io::Call::unlink: live_names.erase(c.path); break;
      case io::Call::mkdir: live_names[c.path] = add(true); break;
      case io::Call::close: fds.erase(c.fd); break;
      case io::Call::syncfs:
        for (Inode& inode : inodes) inode.synced = inode.live;
        synced_names = live_names;
        break;
    }
  }
};

bool under(const std::string& path, const std::string& root) {
  return path.size() > root.size() && path.compare(0, root.size(), root) == 0 && path[root.size()] == '/';
}

}  // namespace

std::size_t materialize_after_cut(const std::vector<RecordedCall>& calls, std::size_t cut, const std::string& root_in,
                                  Loss loss, const std::string& out) {
  const std::string root = fs::absolute(root_in).lexically_normal().string();
  Model model;
  for (std::size_t i = 0; i < cut && i < calls.size(); ++i) model.apply(calls[i]);
  const auto& names = loss == Loss::unsynced ? model.synced_names : model.live_names;
  std::size_t files = 0;
  for (const auto& [name, node] : names) {
    if (!under(name, root)) continue;
    // Lost with a folder above it that did not survive.
    bool reachable = true;
    for (std::string up = Model::parent(name); up != root && under(up, root); up = Model::parent(up)) {
      if (names.count(up) == 0) reachable = false;
    }
    if (!reachable) continue;
    const fs::path target = fs::path(out) / name.substr(root.size() + 1);
    const Inode& inode = model.inodes[node];
    if (inode.folder) {
      fs::create_directories(target);
    } else {
      fs::create_directories(target.parent_path());
      std::ofstream(target, std::ios::binary) << inode.synced;
      ++files;
    }
  }
  return files;
}

}  // namespace rdsf::test
