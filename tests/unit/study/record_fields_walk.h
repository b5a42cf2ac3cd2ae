#pragma once

// Compares two measurements field by field as record_fields.h declares them, so a field the JSON
// writer or reader drops fails the round trip without the test naming it; and checks that a
// sample sets every declared field away from its default, so a new field must be given a value
// before the round trip can pass.
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include <collido/runner/record_fields.h>

namespace collido::study::testdata {

template <typename T>
struct IsCounted : std::false_type {};
template <typename T>
struct IsCounted<CountedField<T>> : std::true_type {};
template <typename T>
struct IsCheckValue : std::false_type {};
template <typename T>
struct IsCheckValue<CheckValueField<T>> : std::true_type {};

template <typename T>
bool sameValue(const T& a, const T& b);

inline bool sameScore(const ContactScore& a, const ContactScore& b) {
  bool same = true;
  visitContactScoreFields(a, [&](const char* name, const auto& x, Absent) {
    visitContactScoreFields(b, [&](const char* other, const auto& y, Absent) {
      if constexpr (std::is_same_v<std::decay_t<decltype(x)>, std::decay_t<decltype(y)>>) {
        if (std::string(name) == other) same = same && sameValue(x, y);
      }
    });
  });
  return same;
}

// Whether two values of a declared field are the same.
template <typename T>
bool sameValue(const T& a, const T& b) {
  if constexpr (IsCounted<T>::value) {
    return a.counted == b.counted && (!a.counted || a.value == b.value);
  } else if constexpr (IsCheckValue<T>::value) {
    return a.get() == b.get();
  } else if constexpr (std::is_same_v<T, UpdateCounters>) {
    return a.counted == b.counted && a.nodes_refit == b.nodes_refit && a.rebuilds == b.rebuilds &&
           a.nodes_rebuilt == b.nodes_rebuilt;
  } else if constexpr (std::is_same_v<T, std::optional<ContactScore>>) {
    return a.has_value() == b.has_value() && (!a || sameScore(*a, *b));
  } else {
    return a == b;
  }
}

// Calls `compare(name, field of a, field of b)` for every field `walk` declares.
template <typename Record, typename Walk, typename Compare>
void eachDeclaredPair(const Record& a, const Record& b, Walk walk, Compare compare) {
  walk(a, [&](const char* name, const auto& x, auto...) {
    bool found = false;
    walk(b, [&](const char* other, const auto& y, auto...) {
      if constexpr (std::is_same_v<std::decay_t<decltype(x)>, std::decay_t<decltype(y)>>) {
        if (!found && std::string(name) == other) {
          found = true;
          compare(name, x, y);
        }
      }
    });
    EXPECT_TRUE(found) << name;
  });
}

inline auto measurementWalk() {
  return [](const QueryMeasurement& m, auto visit) { visitMeasurementFields(m, visit); };
}

inline auto summaryWalk() {
  return [](const QueryMeasurement& m, auto visit) { visitMeasurementSummary(m, visit); };
}

inline auto frameWalk(const QueryMeasurement& m) {
  return [&m](const FrameRecord& f, auto visit) {
    visitFrameFields(f, m.counts_bv_tests, m.counts_primitive_tests, visit);
  };
}

/// Every declared field of `a` equals `b`'s: the stored fields, the summary and each frame's.
inline void expectSameDeclaredFields(const QueryMeasurement& a, const QueryMeasurement& b) {
  const auto expectSame = [](const char* name, const auto& x, const auto& y) {
    EXPECT_TRUE(sameValue(x, y)) << name;
  };
  eachDeclaredPair(a, b, measurementWalk(), expectSame);
  eachDeclaredPair(a, b, summaryWalk(), expectSame);
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (std::size_t i = 0; i < a.frames.size(); ++i) {
    SCOPED_TRACE("frame " + std::to_string(i));
    eachDeclaredPair(a.frames[i], b.frames[i], frameWalk(a), expectSame);
  }
}

/// The declared stored fields (measurement and frame) that none of `samples` sets away from a
/// default record's value.
inline std::vector<std::string> fieldsLeftAtDefault(const std::vector<QueryMeasurement>& samples) {
  std::vector<std::string> left;
  const QueryMeasurement empty;
  const FrameRecord no_frame;
  visitMeasurementFields(empty, [&](const char* name, const auto& defaulted, Absent) {
    using T = std::decay_t<decltype(defaulted)>;
    bool set = false;
    for (const QueryMeasurement& m : samples) {
      visitMeasurementFields(m, [&](const char* other, const auto& value, Absent) {
        if constexpr (std::is_same_v<T, std::decay_t<decltype(value)>>) {
          if (std::string(name) == other && !sameValue(value, defaulted)) set = true;
        }
      });
    }
    if (!set) left.push_back(name);
  });
  visitFrameFields(no_frame, true, true, [&](const char* name, const auto& defaulted, Absent) {
    using T = std::decay_t<decltype(defaulted)>;
    bool set = false;
    for (const QueryMeasurement& m : samples) {
      for (const FrameRecord& f : m.frames) {
        visitFrameFields(f, true, true, [&](const char* other, const auto& value, Absent) {
          if constexpr (std::is_same_v<T, std::decay_t<decltype(value)>>) {
            if (std::string(name) == other && !sameValue(value, defaulted)) set = true;
          }
        });
      }
    }
    if (!set) left.push_back("frames/" + std::string(name));
  });
  return left;
}

}  // namespace collido::study::testdata
