// SignSpec <-> JSON (see sign_spec_json.h). The reader checks every type before reading it, so a
// hostile document gives an error value, never an exception.
#include "notation/sign_spec_json.h"

#include "notation/sign_spec_names.h"

namespace sw::notation {
namespace {

using nlohmann::json;

json dir_json(const Direction& d) { return json::array({d.x, d.y, d.z}); }

json finger_json(const FingerConfig& c) {
  return {{"id", c.id}, {"has_t", c.has_t}, {"t", c.t}, {"spread", c.spread}};
}
json shape_json(const HandShape& s) {
  json fingers = json::array();
  for (const FingerConfig& c : s.fingers) fingers.push_back(finger_json(c));
  return {{"fingers", fingers}, {"hamnosys_base", s.hamnosys_base}};
}
json orientation_json(const Orientation& o) {
  return {{"extended_finger", dir_json(o.extended_finger)}, {"palm", dir_json(o.palm)},
          {"seed_palm", name_of(o.seed_palm)}};
}
json location_json(const Location& l) {
  return {{"kind", name_of(l.kind)},
          {"level", name_of(l.level)},
          {"side", name_of(l.side)},
          {"contact", name_of(l.contact)},
          {"hand_place", name_of(l.hand_place)},
          {"finger", l.finger},
          {"contact_part", l.contact_part ? json(name_of(*l.contact_part)) : json(nullptr)},
          {"contact_finger", l.contact_finger},
          {"seed_id", l.seed_id}};
}
json hand_json(const HandSpec& h) {
  return {{"shape", shape_json(h.shape)},
          {"orientation", orientation_json(h.orientation)},
          {"location", location_json(h.location)}};
}
json movement_json(const Movement& m) {
  return {{"kind", name_of(m.kind)},
          {"direction", dir_json(m.direction)},
          {"arc_bulge", dir_json(m.arc_bulge)},
          {"circle_axis", dir_json(m.circle_axis)},
          {"ellipse_axis", dir_json(m.ellipse_axis)},
          {"clockwise", m.clockwise},
          {"size", name_of(m.size)},
          {"manner", name_of(m.manner)},
          {"to_shape", m.to_shape ? shape_json(*m.to_shape) : json(nullptr)},
          {"to_orientation", m.to_orientation ? orientation_json(*m.to_orientation) : json(nullptr)},
          {"to_location", m.to_location ? location_json(*m.to_location) : json(nullptr)},
          {"alternating", m.alternating}};
}

// ---- reading: each getter checks presence and type and names the field on failure.
struct In {
  std::string* error;
  bool fail(const std::string& path, const char* what) {
    if (error->empty()) *error = path + ": expected " + what;
    return false;
  }
  const json* field(const json& j, const char* key, const std::string& path) {
    if (!j.is_object()) {
      fail(path, "an object");
      return nullptr;
    }
    const auto it = j.find(key);
    if (it == j.end()) {
      fail(path + "." + key, "a value (missing)");
      return nullptr;
    }
    return &*it;
  }
  template <typename E>
  bool name(const json& j, const char* key, const std::string& path, E* out) {
    const json* v = field(j, key, path);
    if (!v) return false;
    if (!v->is_string() || !from_name(v->get_ref<const std::string&>(), out)) {
      return fail(path + "." + key, "a known name");
    }
    return true;
  }
  bool boolean(const json& j, const char* key, const std::string& path, bool* out) {
    const json* v = field(j, key, path);
    if (!v) return false;
    if (!v->is_boolean()) return fail(path + "." + key, "true or false");
    *out = v->get<bool>();
    return true;
  }
  bool number(const json& j, const char* key, const std::string& path, double lo, double hi, double* out) {
    const json* v = field(j, key, path);
    if (!v) return false;
    if (!v->is_number()) return fail(path + "." + key, "a number");
    const double d = v->get<double>();
    if (!(d >= lo && d <= hi)) return fail(path + "." + key, "a number in range");
    *out = d;
    return true;
  }
  template <typename T>
  bool integer(const json& j, const char* key, const std::string& path, int lo, int hi, T* out) {
    double d = 0;
    if (!number(j, key, path, lo, hi, &d)) return false;
    if (d != static_cast<double>(static_cast<long long>(d))) return fail(path + "." + key, "a whole number");
    *out = static_cast<T>(d);
    return true;
  }
  bool string(const json& j, const char* key, const std::string& path, std::string* out) {
    const json* v = field(j, key, path);
    if (!v) return false;
    if (!v->is_string()) return fail(path + "." + key, "a string");
    *out = v->get<std::string>();
    return true;
  }
  bool direction(const json& j, const char* key, const std::string& path, Direction* out) {
    const json* v = field(j, key, path);
    if (!v) return false;
    if (!v->is_array() || v->size() != 3) return fail(path + "." + key, "[x, y, z]");
    std::int8_t c[3];
    for (int i = 0; i < 3; ++i) {
      const json& e = (*v)[static_cast<std::size_t>(i)];
      if (!e.is_number_integer() || e.get<long long>() < -1 || e.get<long long>() > 1) {
        return fail(path + "." + key, "components -1, 0 or 1");
      }
      c[i] = static_cast<std::int8_t>(e.get<long long>());
    }
    *out = Direction{c[0], c[1], c[2]};
    return true;
  }
  bool shape(const json& j, const std::string& path, HandShape* out) {
    const json* f = field(j, "fingers", path);
    if (!f) return false;
    if (!f->is_array() || f->size() != kFingerCount) return fail(path + ".fingers", "5 fingers");
    for (int k = 0; k < kFingerCount; ++k) {
      const json& c = (*f)[static_cast<std::size_t>(k)];
      const std::string p = path + ".fingers[" + std::to_string(k) + "]";
      FingerConfig& fc = out->fingers[k];
      double t = 0, s = 0;
      if (!integer(c, "id", p, 0, k == 0 ? static_cast<int>(kThumbAlongside) : static_cast<int>(kFingerDoubleHooked), &fc.id) ||
          !boolean(c, "has_t", p, &fc.has_t) || !number(c, "t", p, 0, 1, &t) ||
          !number(c, "spread", p, 0, 1, &s)) {
        return false;
      }
      fc.t = static_cast<float>(t);
      fc.spread = static_cast<float>(s);
    }
    return string(j, "hamnosys_base", path, &out->hamnosys_base);
  }
  bool orientation(const json& j, const std::string& path, Orientation* out) {
    return direction(j, "extended_finger", path, &out->extended_finger) &&
           direction(j, "palm", path, &out->palm) && name(j, "seed_palm", path, &out->seed_palm);
  }
  bool location(const json& j, const std::string& path, Location* out) {
    if (!name(j, "kind", path, &out->kind) || !name(j, "level", path, &out->level) ||
        !name(j, "side", path, &out->side) || !name(j, "contact", path, &out->contact) ||
        !name(j, "hand_place", path, &out->hand_place) || !integer(j, "finger", path, -1, 4, &out->finger) ||
        !integer(j, "contact_finger", path, -1, 4, &out->contact_finger) ||
        !integer(j, "seed_id", path, 0, 1000, &out->seed_id)) {
      return false;
    }
    const json* part = field(j, "contact_part", path);
    if (!part) return false;
    if (part->is_null()) {
      out->contact_part.reset();
    } else {
      HandPlace p;
      if (!part->is_string() || !from_name(part->get_ref<const std::string&>(), &p)) {
        return fail(path + ".contact_part", "null or a place name");
      }
      out->contact_part = p;
    }
    return true;
  }
  bool hand(const json& j, const std::string& path, HandSpec* out) {
    const json* s = field(j, "shape", path);
    const json* o = s ? field(j, "orientation", path) : nullptr;
    const json* l = o ? field(j, "location", path) : nullptr;
    return l && shape(*s, path + ".shape", &out->shape) &&
           orientation(*o, path + ".orientation", &out->orientation) &&
           location(*l, path + ".location", &out->location);
  }
  bool movement(const json& j, const std::string& path, Movement* m) {
    if (!name(j, "kind", path, &m->kind) || !direction(j, "direction", path, &m->direction) ||
        !direction(j, "arc_bulge", path, &m->arc_bulge) ||
        !direction(j, "circle_axis", path, &m->circle_axis) ||
        !direction(j, "ellipse_axis", path, &m->ellipse_axis) ||
        !boolean(j, "clockwise", path, &m->clockwise) || !name(j, "size", path, &m->size) ||
        !name(j, "manner", path, &m->manner) || !boolean(j, "alternating", path, &m->alternating)) {
      return false;
    }
    const json* s = field(j, "to_shape", path);
    const json* o = s ? field(j, "to_orientation", path) : nullptr;
    const json* l = o ? field(j, "to_location", path) : nullptr;
    if (!l) return false;
    if (!s->is_null()) {
      HandShape v;
      if (!shape(*s, path + ".to_shape", &v)) return false;
      m->to_shape = v;
    }
    if (!o->is_null()) {
      Orientation v;
      if (!orientation(*o, path + ".to_orientation", &v)) return false;
      m->to_orientation = v;
    }
    if (!l->is_null()) {
      Location v;
      if (!location(*l, path + ".to_location", &v)) return false;
      m->to_location = v;
    }
    return true;
  }
  bool movements(const json& j, const std::string& path, std::vector<Movement>* out) {
    if (!j.is_array()) return fail(path, "an array of movements");
    for (std::size_t i = 0; i < j.size(); ++i) {
      Movement m;
      if (!movement(j[i], path + "[" + std::to_string(i) + "]", &m)) return false;
      out->push_back(std::move(m));
    }
    return true;
  }
};

}  // namespace

json sign_to_json(const SignSpec& s) {
  json steps = json::array();
  for (const MovementStep& step : s.movements) {
    json d = json::array(), n = json::array();
    for (const Movement& m : step.dominant) d.push_back(movement_json(m));
    for (const Movement& m : step.nondominant) n.push_back(movement_json(m));
    json js = {{"dominant", d}, {"nondominant", n}};
    // Written only when set, so that every other sign's JSON (stored by the server) is as before.
    if (step.nondominant_stays) js["nondominant_stays"] = true;
    steps.push_back(std::move(js));
  }
  const NonManual& nm = s.nonmanual;
  return {{"gloss", s.gloss},
          {"dominant", hand_json(s.dominant)},
          {"nondominant", s.nondominant ? hand_json(*s.nondominant) : json(nullptr)},
          {"symmetry", name_of(s.symmetry)},
          {"nondominant_is_place", s.nondominant_is_place},
          {"one_hand_is_nondominant", s.one_hand_is_nondominant},
          {"movements", steps},
          {"repetition", {{"kind", name_of(s.repetition.kind)}, {"count", s.repetition.count}}},
          {"nonmanual",
           {{"mouthing", nm.mouthing},
            {"mouth_gesture", nm.mouth_gesture},
            {"eyebrows", nm.eyebrows},
            {"expression", nm.expression},
            {"expression_intensity", nm.expression_intensity},
            {"head", nm.head},
            {"gaze", nm.gaze}}}};
}

bool sign_from_json(const json& j, SignSpec* out, std::string* error) {
  std::string local_error;
  In in{error ? error : &local_error};
  in.error->clear();
  SignSpec s;
  const json* dom = in.field(j, "dominant", "sign");
  const json* nd = dom ? in.field(j, "nondominant", "sign") : nullptr;
  const json* mv = nd ? in.field(j, "movements", "sign") : nullptr;
  const json* rep = mv ? in.field(j, "repetition", "sign") : nullptr;
  const json* nm = rep ? in.field(j, "nonmanual", "sign") : nullptr;
  if (!nm || !in.string(j, "gloss", "sign", &s.gloss) || !in.hand(*dom, "sign.dominant", &s.dominant) ||
      !in.name(j, "symmetry", "sign", &s.symmetry) ||
      !in.boolean(j, "nondominant_is_place", "sign", &s.nondominant_is_place) ||
      !in.name(*rep, "kind", "sign.repetition", &s.repetition.kind) ||
      !in.integer(*rep, "count", "sign.repetition", 0, 1000, &s.repetition.count)) {
    return false;
  }
  // Optional: JSON written before the field existed reads as a sign of the dominant hand.
  if (j.contains("one_hand_is_nondominant") &&
      !in.boolean(j, "one_hand_is_nondominant", "sign", &s.one_hand_is_nondominant))
    return false;
  if (!nd->is_null()) {
    HandSpec h;
    if (!in.hand(*nd, "sign.nondominant", &h)) return false;
    s.nondominant = h;
  }
  if (!mv->is_array()) return in.fail("sign.movements", "an array");
  for (std::size_t i = 0; i < mv->size(); ++i) {
    const std::string p = "sign.movements[" + std::to_string(i) + "]";
    const json& step = (*mv)[i];
    const json* d = in.field(step, "dominant", p);
    const json* n = d ? in.field(step, "nondominant", p) : nullptr;
    MovementStep ms;
    if (!n || !in.movements(*d, p + ".dominant", &ms.dominant) ||
        !in.movements(*n, p + ".nondominant", &ms.nondominant)) {
      return false;
    }
    if (step.is_object() && step.contains("nondominant_stays") &&
        !in.boolean(step, "nondominant_stays", p, &ms.nondominant_stays)) {
      return false;
    }
    s.movements.push_back(std::move(ms));
  }
  double intensity = 0;
  if (!in.string(*nm, "mouthing", "sign.nonmanual", &s.nonmanual.mouthing) ||
      !in.string(*nm, "mouth_gesture", "sign.nonmanual", &s.nonmanual.mouth_gesture) ||
      !in.string(*nm, "eyebrows", "sign.nonmanual", &s.nonmanual.eyebrows) ||
      !in.string(*nm, "expression", "sign.nonmanual", &s.nonmanual.expression) ||
      !in.number(*nm, "expression_intensity", "sign.nonmanual", 0, 1, &intensity) ||
      !in.string(*nm, "head", "sign.nonmanual", &s.nonmanual.head) ||
      !in.string(*nm, "gaze", "sign.nonmanual", &s.nonmanual.gaze)) {
    return false;
  }
  s.nonmanual.expression_intensity = static_cast<float>(intensity);
  *out = std::move(s);
  return true;
}

std::string sign_to_json_text(const SignSpec& sign) { return sign_to_json(sign).dump(); }

bool sign_from_json_text(std::string_view text, SignSpec* sign, std::string* error) {
  const json j = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) {
    if (error) *error = "not valid JSON";
    return false;
  }
  return sign_from_json(j, sign, error);
}

json diagnostic_to_json(const Diagnostic& d) {
  return {{"severity", d.severity == Severity::Error ? "error" : "warning"},
          {"line", d.line},
          {"column", d.column},
          {"offset", d.offset},
          {"length", d.length},
          {"symbol", d.symbol},
          {"message", d.message}};
}

json diagnostics_to_json(const std::vector<Diagnostic>& diagnostics) {
  json out = json::array();
  for (const Diagnostic& d : diagnostics) out.push_back(diagnostic_to_json(d));
  return out;
}

json parse_result_to_json(const std::vector<SignParse>& signs, NotationFormat format) {
  json list = json::array();
  json all = json::array();
  bool ok = !signs.empty();
  for (const SignParse& s : signs) {
    list.push_back({{"gloss", s.gloss},
                    {"line", s.line},
                    {"ok", s.ok()},
                    {"spec", s.spec ? sign_to_json(*s.spec) : json(nullptr)},
                    {"diagnostics", diagnostics_to_json(s.diagnostics)}});
    for (const Diagnostic& d : s.diagnostics) all.push_back(diagnostic_to_json(d));
    ok = ok && s.ok();
  }
  return {{"format", format_name(format)}, {"ok", ok}, {"signs", list}, {"diagnostics", all}};
}

}  // namespace sw::notation
