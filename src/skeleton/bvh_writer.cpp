// BVH writer: Bvh -> text with a fixed number of decimals, so that read(write(x)) reproduces x to
// the printed precision and write(read(write(x))) is byte-identical (bvh.h).
#include <cstdio>
#include <string>
#include <vector>

#include "skeleton/bvh.h"

namespace sw::skeleton {
namespace {

class Writer {
 public:
  Writer(const Bvh& bvh, const BvhWriteOptions& options) : bvh_(bvh), decimals_(options.decimals) {
    // The printf precision is bounded so that a wild option cannot make a number of 1e6 digits.
    if (decimals_ < 0) decimals_ = 0;
    if (decimals_ > 17) decimals_ = 17;
    children_.resize(bvh.joints.size());
    for (std::size_t i = 0; i < bvh.joints.size(); ++i) {
      const int p = bvh.joints[i].parent;
      if (p >= 0 && static_cast<std::size_t>(p) < bvh.joints.size())
        children_[static_cast<std::size_t>(p)].push_back(static_cast<int>(i));
    }
  }

  std::string write() {
    out_ += "HIERARCHY\n";
    for (std::size_t i = 0; i < bvh_.joints.size(); ++i) {
      if (bvh_.joints[i].parent < 0) write_joint(static_cast<int>(i), 0);
    }
    out_ += "MOTION\n";
    out_ += "Frames: " + std::to_string(bvh_.frame_count) + "\n";
    out_ += "Frame Time: " + number(bvh_.frame_time_s) + "\n";
    // Frames list channels in the order joints appear in the text (depth first), which is the
    // order `file_order_` recorded; a Bvh whose array is not in that order is permuted here.
    const int channels = bvh_.channel_count();
    for (int f = 0; f < bvh_.frame_count; ++f) {
      const double* values = bvh_.frame(f);
      bool first = true;
      for (int joint : file_order_) {
        const int offset = bvh_.channel_offset(joint);
        const int count =
            static_cast<int>(bvh_.joints[static_cast<std::size_t>(joint)].channels.size());
        for (int c = 0; c < count && offset + c < channels; ++c) {
          if (!first) out_ += ' ';
          out_ += number(values[offset + c]);
          first = false;
        }
      }
      out_ += '\n';
    }
    return std::move(out_);
  }

 private:
  std::string number(double v) const {
    char buf[512];
    std::snprintf(buf, sizeof buf, "%.*f", decimals_, v);
    std::string s(buf);
    // "-0.000000" reads back as -0.0 and prints the same, but it is noise: rounding made it zero.
    if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
    return s;
  }

  void indent(int depth) { out_.append(static_cast<std::size_t>(depth), '\t'); }

  void write_offset(const glm::dvec3& v, int depth) {
    indent(depth);
    out_ += "OFFSET " + number(v.x) + " " + number(v.y) + " " + number(v.z) + "\n";
  }

  void write_joint(int index, int depth) {
    const BvhJoint& j = bvh_.joints[static_cast<std::size_t>(index)];
    file_order_.push_back(index);
    indent(depth);
    out_ += (j.parent < 0 ? "ROOT " : "JOINT ") + j.name + "\n";
    indent(depth);
    out_ += "{\n";
    write_offset(j.offset, depth + 1);
    indent(depth + 1);
    out_ += "CHANNELS " + std::to_string(j.channels.size());
    for (BvhChannel c : j.channels) out_ += std::string(" ") + bvh_channel_name(c);
    out_ += "\n";
    for (int child : children_[static_cast<std::size_t>(index)]) write_joint(child, depth + 1);
    if (j.has_end_site) {
      indent(depth + 1);
      out_ += "End Site\n";
      indent(depth + 1);
      out_ += "{\n";
      write_offset(j.end_site_offset, depth + 2);
      indent(depth + 1);
      out_ += "}\n";
    }
    indent(depth);
    out_ += "}\n";
  }

  const Bvh& bvh_;
  int decimals_;
  std::vector<std::vector<int>> children_;
  std::vector<int> file_order_;
  std::string out_;
};

}  // namespace

std::string write_bvh(const Bvh& bvh, const BvhWriteOptions& options) {
  return Writer(bvh, options).write();
}

}  // namespace sw::skeleton
