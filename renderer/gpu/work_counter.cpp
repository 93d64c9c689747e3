#include "gpu/work_counter.hpp"

#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "common/error.hpp"

namespace facet::gpu {

namespace {

// SPIR-V opcodes (SPIR-V 1.5 specification, section 3.52) and GLSL.std.450 instruction numbers.
enum Op : uint32_t {
  OpName = 5,
  OpExtInstImport = 11,
  OpExtInst = 12,
  OpTypeInt = 21,
  OpTypeFloat = 22,
  OpTypeVector = 23,
  OpConstant = 43,
  OpFunction = 54,
  OpVariable = 59,
  OpLoad = 61,
  OpStore = 62,
  OpImageFetch = 95,
  OpFNegate = 127,
  OpIAdd = 128,
  OpFAdd = 129,
  OpFSub = 131,
  OpFMul = 133,
  OpFDiv = 136,
  OpFRem = 140,
  OpFMod = 141,
  OpVectorTimesScalar = 142,
  OpDot = 148,
  OpPhi = 245,
  OpLabel = 248,
};
enum Glsl : uint32_t {
  Round = 1, RoundEven = 2, Trunc = 3, FAbs = 4, FSign = 6, Floor = 8, Ceil = 9, Fract = 10,
  Sin = 13, Cos = 14, Tan = 15, Asin = 16, Acos = 17, Atan = 18, Sinh = 19, Cosh = 20, Tanh = 21,
  Asinh = 22, Acosh = 23, Atanh = 24, Atan2 = 25, Pow = 26, Exp = 27, Log = 28, Exp2 = 29, Log2 = 30,
  Sqrt = 31, InverseSqrt = 32, FMin = 37, FMax = 40, FClamp = 43, FMix = 46, Step = 48, SmoothStep = 49,
  Fma = 50, Length = 66, Distance = 67, Cross = 68, Normalize = 69, Reflect = 71,
};

// FMA-equivalents: one float32 lane of an add, a multiply or a fused multiply-add (what the probe
// measures, gpu/peak_probe.hpp). Division and square roots cost kRootCost, exp, log and the
// trigonometric functions kTranscendentalCost: lavapipe's rates of sqrt(x + 1) and exp against its FMA
// rate (../shared/PLATFORM.md, section 3: 11.1 and 7.3 G/s against 35.1 G FMA/s, so 3.2 and 4.8).
constexpr uint32_t kRootCost = 3;
constexpr uint32_t kTranscendentalCost = 5;

// Per lane of its result, the cost of a GLSL.std.450 instruction on floats; vector-to-scalar ones by
// their operand's width n in extended_cost.
std::optional<uint32_t> extended_lane_cost(uint32_t instruction) {
  switch (instruction) {
    case Round: case RoundEven: case Trunc: case FAbs: case FSign: case Floor: case Ceil: case Fract:
    case FMin: case FMax: case Fma: case Step:
      return 1;
    case FClamp: case FMix:  // min and max; a subtraction and an fma
      return 2;
    case SmoothStep:  // t = clamp((x - a) / (b - a)): 2 subtractions, a division, a clamp; t t (3 - 2 t): 3
      return 2 + kRootCost + 2 + 3;
    case Sqrt: case InverseSqrt:
      return kRootCost;
    case Sin: case Cos: case Tan: case Asin: case Acos: case Atan: case Sinh: case Cosh: case Tanh:
    case Asinh: case Acosh: case Atanh: case Atan2: case Exp: case Log: case Exp2: case Log2:
      return kTranscendentalCost;
    case Pow:  // exp2(y log2(x))
      return 2 * kTranscendentalCost + 1;
    default:
      return std::nullopt;
  }
}

struct Module {
  std::map<uint32_t, uint32_t> float_lanes;  // float scalar/vector type id -> lanes
  std::map<uint32_t, uint32_t> type_of;      // value id -> its type id
  uint32_t glsl_set = 0;                     // the GLSL.std.450 import's id
};

uint32_t lanes(const Module& m, uint32_t type) {
  const auto it = m.float_lanes.find(type);
  return it == m.float_lanes.end() ? 0 : it->second;
}

uint32_t operand_lanes(const Module& m, uint32_t value) {
  const auto it = m.type_of.find(value);
  return it == m.type_of.end() ? 0 : lanes(m, it->second);
}

// The FMA-equivalents of one instruction (`w`: its words).
uint32_t arithmetic_cost(const Module& m, std::span<const uint32_t> w) {
  const uint32_t op = w[0] & 0xffffu;
  if (w.size() < 4) return 0;
  const uint32_t n = lanes(m, w[1]);
  switch (op) {
    case OpFAdd: case OpFSub: case OpFMul: case OpVectorTimesScalar:
      return n;
    case OpFDiv:
      return n * kRootCost;
    case OpFRem: case OpFMod:  // a division, a truncation and an fma
      return n * (kRootCost + 2);
    case OpDot:  // n fmas
      return operand_lanes(m, w[3]);
    case OpExtInst: {
      if (w.size() < 6 || w[3] != m.glsl_set) return 0;
      const uint32_t instruction = w[4];
      const uint32_t x = operand_lanes(m, w[5]);
      switch (instruction) {
        case Length: return x + kRootCost;                   // dot, sqrt
        case Distance: return 2 * x + kRootCost;             // subtraction, dot, sqrt
        case Normalize: return 2 * x + kRootCost;            // dot, inversesqrt, scaling
        case Cross: return 6;                                // 3 multiplications, 3 fmas
        case Reflect: return 3 * x;                          // dot, 2 (n.i), i - that n
        default: return n * extended_lane_cost(instruction).value_or(0);
      }
    }
    default:
      return 0;
  }
}

std::string literal_string(std::span<const uint32_t> words) {
  std::string text(words.size() * 4, '\0');
  std::memcpy(text.data(), words.data(), text.size());
  return text.substr(0, text.find('\0'));
}

}  // namespace

std::vector<uint32_t> instrument_work_counts(std::span<const uint32_t> spirv) {
  if (spirv.size() < 5 || spirv[0] != 0x07230203u) throw Error("work counter: not a SPIR-V module");
  Module m;
  uint32_t bound = spirv[3];
  uint32_t counter_fma = 0, counter_reads = 0, uint_type = 0;
  size_t first_function = spirv.size();
  std::vector<size_t> starts;  // every instruction's first word
  for (size_t at = 5; at < spirv.size();) {
    const uint32_t count = spirv[at] >> 16, op = spirv[at] & 0xffffu;
    if (count == 0 || at + count > spirv.size()) throw Error("work counter: malformed SPIR-V");
    const std::span<const uint32_t> w = spirv.subspan(at, count);
    starts.push_back(at);
    if (op == OpName && count >= 3) {
      const std::string name = literal_string(w.subspan(2));
      if (name == "facet_work_fma") counter_fma = w[1];
      if (name == "facet_work_reads") counter_reads = w[1];
    } else if (op == OpExtInstImport && literal_string(w.subspan(2)) == "GLSL.std.450") {
      m.glsl_set = w[1];
    } else if (op == OpTypeFloat && count == 3 && w[2] == 32) {
      m.float_lanes[w[1]] = 1;
    } else if (op == OpTypeVector && count == 4 && m.float_lanes.count(w[2])) {
      m.float_lanes[w[1]] = w[3];
    } else if (op == OpTypeInt && count == 4 && w[2] == 32 && w[3] == 0) {
      uint_type = w[1];
    } else if (op == OpFunction && first_function == spirv.size()) {
      first_function = at;
    }
    // Within functions, an instruction whose first operand is a type has a result id next
    // (ids are unique, so no other operand can be a type's id).
    if (at >= first_function && count >= 3 && (m.float_lanes.count(w[1]) || w[1] == uint_type)) m.type_of[w[2]] = w[1];
    at += count;
  }
  if (!counter_fma || !counter_reads || !uint_type)
    throw Error("work counter: the shader declares no uint facet_work_fma and facet_work_reads");
  std::set<uint32_t> variables;
  for (size_t at : starts)
    if ((spirv[at] & 0xffffu) == OpVariable && at < first_function) variables.insert(spirv[at + 2]);
  if (!variables.count(counter_fma) || !variables.count(counter_reads))
    throw Error("work counter: the counters are not global variables");

  // Per block: its cost, and where its increments go (after the label, phis and, in a function's
  // first block, its variables).
  struct Block {
    size_t insert_at;
    uint32_t fma = 0, reads = 0;
  };
  std::vector<Block> blocks;
  for (size_t i = 0; i < starts.size(); ++i) {
    const size_t at = starts[i];
    const uint32_t op = spirv[at] & 0xffffu;
    if (op == OpLabel) {
      size_t j = i + 1;
      while (j < starts.size() && ((spirv[starts[j]] & 0xffffu) == OpPhi || (spirv[starts[j]] & 0xffffu) == OpVariable))
        ++j;
      blocks.push_back({j < starts.size() ? starts[j] : spirv.size()});
      continue;
    }
    if (blocks.empty() || at < first_function) continue;
    const std::span<const uint32_t> w = spirv.subspan(at, spirv[at] >> 16);
    blocks.back().fma += arithmetic_cost(m, w);
    if (op == OpImageFetch) ++blocks.back().reads;
  }

  // One constant per distinct increment, declared before the first function.
  std::map<uint32_t, uint32_t> constant_id;
  for (const Block& b : blocks)
    for (uint32_t v : {b.fma, b.reads})
      if (v > 0 && !constant_id.count(v)) constant_id[v] = bound++;
  std::vector<uint32_t> out(spirv.begin(), spirv.begin() + first_function);
  for (const auto& [value, id] : constant_id) out.insert(out.end(), {(4u << 16) | OpConstant, uint_type, id, value});
  size_t copied = first_function;
  auto increment = [&](uint32_t counter, uint32_t value) {
    if (value == 0) return;
    const uint32_t loaded = bound++, sum = bound++;
    out.insert(out.end(), {(4u << 16) | OpLoad, uint_type, loaded, counter});
    out.insert(out.end(), {(5u << 16) | OpIAdd, uint_type, sum, loaded, constant_id.at(value)});
    out.insert(out.end(), {(3u << 16) | OpStore, counter, sum});
  };
  for (const Block& b : blocks) {
    out.insert(out.end(), spirv.begin() + copied, spirv.begin() + b.insert_at);
    copied = b.insert_at;
    increment(counter_fma, b.fma);
    increment(counter_reads, b.reads);
  }
  out.insert(out.end(), spirv.begin() + copied, spirv.end());
  out[3] = bound;
  return out;
}

}  // namespace facet::gpu
