#include "mask_stack.h"

#include <fcntl.h>
#include <unistd.h>
#include <zip.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "ctb_format.h"
#include "goo_format.h"
#include "photon_workshop_format.h"
#include "slicereuse/util/error.h"

namespace slicereuse {
namespace {

namespace fs = std::filesystem;

// The layer number ending a PNG name ("job00012.png" -> 12) from at most its last max_digits
// digits, or -1 when there is none.
long long layer_number(const std::string& name, size_t max_digits = 12) {
  if (name.size() < 5) return -1;
  std::string ext = name.substr(name.size() - 4);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".png") return -1;
  size_t first = name.size() - 4;
  while (first > 0 && name.size() - 4 - first < max_digits &&
         std::isdigit(static_cast<unsigned char>(name[first - 1])))
    --first;
  const size_t digits = name.size() - 4 - first;
  if (digits == 0 || digits > 12) return -1;
  return std::stoll(name.substr(first, digits));
}

// Digits of a zero-padded layer number in a stack of L layers: 5 (PrusaSlicer's %.5d) or as many
// as L - 1 needs. Digits before those belong to the job name ("member_001" + "00012").
size_t number_width(size_t L) {
  size_t w = 1;
  for (size_t n = L > 0 ? L - 1 : 0; n >= 10; n /= 10) ++w;
  return std::max<size_t>(5, w);
}

// Places each named image at its layer number; throws on repeats and gaps.
void place(const std::string& stack, std::vector<std::pair<long long, std::string>>& found,
           std::vector<std::string>& names, std::vector<uint64_t>* entry,
           const std::vector<uint64_t>& found_entry) {
  if (found.empty()) throw Error("mask stack '" + stack + "' holds no layer images (NNNNN.png)");
  const size_t L = found.size();
  names.assign(L, std::string());
  if (entry) entry->assign(L, 0);
  const size_t width = number_width(L);
  for (size_t i = 0; i < L; ++i) {
    const long long k = layer_number(found[i].second, width);
    if (k >= static_cast<long long>(L))
      throw Error("mask stack '" + stack + "' has " + std::to_string(L) + " layer images but '" +
                  found[i].second + "' is numbered " + std::to_string(k) +
                  ": layers are missing");
    if (!names[size_t(k)].empty())
      throw Error("mask stack '" + stack + "' has two images for layer " + std::to_string(k) +
                  ": '" + names[size_t(k)] + "' and '" + found[i].second + "'");
    names[size_t(k)] = found[i].second;
    if (entry) (*entry)[size_t(k)] = found_entry[i];
  }
}

// A file that begins as a .goo does (its magic at bytes 4..11), whatever its name.
bool starts_as_goo(const std::string& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), std::fclose);
  uint8_t head[12];
  return f && std::fread(head, 1, sizeof head, f.get()) == sizeof head &&
         std::memcmp(head + kGooMagicAt, kGooMagic, sizeof kGooMagic) == 0;
}

// A file that begins as an Anycubic Photon Workshop file does ("ANYCUBIC"), whatever its name.
bool starts_as_photon_workshop(const std::string& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), std::fclose);
  char head[sizeof kPwsMark];
  return f && std::fread(head, 1, sizeof head, f.get()) == sizeof head && std::memcmp(head, kPwsMark, sizeof head) == 0;
}

// A file that begins as a .ctb does (its magic, little-endian, in bytes 0..3), whatever its name.
bool starts_as_ctb(const std::string& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), std::fclose);
  uint8_t head[4];
  if (!f || std::fread(head, 1, sizeof head, f.get()) != sizeof head) return false;
  const uint32_t magic = uint32_t(head[0]) | uint32_t(head[1]) << 8 | uint32_t(head[2]) << 16 | uint32_t(head[3]) << 24;
  return magic == kCtbMagic || magic == kCtbMagicV4 || magic == kCtbEncryptedMagic;
}

std::string zip_message(int code) {
  zip_error_t e;
  zip_error_init_with_code(&e, code);
  std::string s = zip_error_strerror(&e);
  zip_error_fini(&e);
  return s;
}

}  // namespace

std::string lower_extension(const std::string& path) {
  const size_t dot = path.find_last_of("./");
  if (dot == std::string::npos || path[dot] != '.') return "";
  std::string ext = path.substr(dot);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string mask_layer_file_name(const std::string& prefix, size_t k) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%05zu", k);
  return prefix + digits + ".png";
}

MaskStack::MaskStack(const std::string& path) : path_(path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) throw Error("mask stack '" + path + "' does not exist");
  std::vector<std::pair<long long, std::string>> found;
  std::vector<uint64_t> found_entry;
  if (fs::is_directory(st)) {
    for (fs::directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      const long long k = layer_number(name);
      if (k >= 0 && it->is_regular_file()) found.emplace_back(k, name);
    }
    if (ec) throw Error("cannot list mask folder '" + path + "': " + ec.message());
    place(path, found, names_, nullptr, found_entry);
    return;
  }
  const std::string ext = lower_extension(path);
  kind_ = ext == ".goo" || starts_as_goo(path)                                   ? PrintFile::Goo
          : ext == ".ctb" || starts_as_ctb(path)                                 ? PrintFile::Ctb
          : photon_workshop_kind(ext) || starts_as_photon_workshop(path) ? PrintFile::PhotonWorkshop
                                                                                 : PrintFile::None;
  if (kind_ != PrintFile::None) {
    file_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (file_ < 0) throw Error("cannot open '" + path + "': " + std::strerror(errno));
    size_t layers = 0;
    try {
      if (kind_ == PrintFile::Goo) {
        goo_index_ = index_goo_file(file_, path);
        layers = goo_index_.data_at.size();
      } else if (kind_ == PrintFile::Ctb) {
        ctb_index_ = index_ctb_file(file_, path);
        layers = ctb_index_.data_at.size();
      } else {
        pws_index_ = index_photon_workshop_file(file_, path);
        layers = pws_index_.data_at.size();
      }
      if (layers == 0) throw Error("mask stack '" + path + "' holds no layers");
    } catch (...) {
      ::close(file_);
      file_ = -1;
      throw;
    }
    names_.resize(layers);
    return;
  }
  int code = 0;
  zip_ = zip_open(path.c_str(), ZIP_RDONLY, &code);
  if (!zip_)
    throw Error("mask stack '" + path + "' is neither a folder nor a readable .sl1 archive nor a print file: " +
                zip_message(code));
  const zip_int64_t n = zip_get_num_entries(zip_, 0);
  for (zip_int64_t i = 0; i < n; ++i) {
    const char* entry = zip_get_name(zip_, zip_uint64_t(i), 0);
    if (!entry || std::strchr(entry, '/')) continue;  // thumbnails live in thumbnail/
    const long long k = layer_number(entry);
    if (k < 0) continue;
    found.emplace_back(k, entry);
    found_entry.push_back(zip_uint64_t(i));
  }
  try {
    place(path, found, names_, &entry_, found_entry);
  } catch (...) {
    zip_discard(zip_);
    zip_ = nullptr;
    throw;
  }
}

MaskStack::~MaskStack() {
  if (zip_) zip_discard(zip_);
  if (file_ >= 0) ::close(file_);
}

std::string MaskStack::layer_name(size_t k) const {
  if (file_ >= 0) return path_ + ": layer " + std::to_string(k);
  return zip_ ? path_ + ":" + names_[k] : (fs::path(path_) / names_[k]).string();
}

void MaskStack::decode(size_t k, const std::vector<uint8_t>& bytes, MaskImage& out) const {
  switch (kind_) {
    case PrintFile::Goo:
      return decode_goo_layer(bytes.data(), bytes.size(), goo_index_.width, goo_index_.height, layer_name(k), out);
    case PrintFile::Ctb:
      return decode_ctb_layer(bytes.data(), bytes.size(), ctb_index_.width, ctb_index_.height, ctb_index_.key, k,
                              layer_name(k), out);
    case PrintFile::PhotonWorkshop:
      return decode_pw0_layer(bytes.data(), bytes.size(), pws_index_.width, pws_index_.height, layer_name(k), out);
    case PrintFile::None:
      return decode_mask_png(bytes.data(), bytes.size(), layer_name(k), out);
  }
}

void MaskStack::read(size_t k, std::vector<uint8_t>& bytes) {
  switch (kind_) {
    case PrintFile::Goo:
      return read_goo_layer(file_, goo_index_, k, layer_name(k), bytes);
    case PrintFile::Ctb:
      return read_ctb_layer(file_, ctb_index_, k, layer_name(k), bytes);
    case PrintFile::PhotonWorkshop:
      return read_photon_workshop_layer(file_, pws_index_, k, layer_name(k), bytes);
    case PrintFile::None:
      break;
  }
  if (!zip_) {
    const std::string file = layer_name(k);
    std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(file.c_str(), "rb"), std::fclose);
    if (!f) throw Error("cannot open '" + file + "': " + std::strerror(errno));
    bytes.clear();
    uint8_t buf[1 << 16];
    size_t got;
    while ((got = std::fread(buf, 1, sizeof buf, f.get())) > 0) bytes.insert(bytes.end(), buf, buf + got);
    if (std::ferror(f.get())) throw Error("cannot read '" + file + "': " + std::strerror(errno));
    return;
  }
  zip_stat_t st;
  if (zip_stat_index(zip_, entry_[k], 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE))
    throw Error("cannot read '" + layer_name(k) + "': " + zip_strerror(zip_));
  std::unique_ptr<zip_file_t, int (*)(zip_file_t*)> f(zip_fopen_index(zip_, entry_[k], 0),
                                                      zip_fclose);
  if (!f) throw Error("cannot read '" + layer_name(k) + "': " + zip_strerror(zip_));
  bytes.resize(st.size);
  // Reading to the end (and one byte past) makes libzip check the entry's CRC.
  uint8_t extra;
  const zip_int64_t got = zip_fread(f.get(), bytes.data(), st.size);
  const zip_int64_t more = got == zip_int64_t(st.size) ? zip_fread(f.get(), &extra, 1) : 0;
  if (got < 0 || more < 0)
    throw Error("cannot read '" + layer_name(k) + "': " + zip_file_strerror(f.get()));
  if (got != zip_int64_t(st.size) || more != 0)
    throw Error("cannot read '" + layer_name(k) + "': the entry is not " +
                std::to_string(st.size) + " bytes long");
}

}  // namespace slicereuse
