#pragma once

// Checks shared by the bad-input tests: a rejection must carry the right code and a message that
// names the culprit (file, JSON path, plugin) and the problem.
#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <string>

#include <gtest/gtest.h>

#include <collido/status.h>

namespace collido::test {

inline std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/// Whether `message` contains one of the '|'-separated alternatives of `words`, ignoring case.
inline bool containsAnyOf(const std::string& message, const std::string& words) {
  const std::string haystack = lowerCase(message);
  std::size_t begin = 0;
  while (begin <= words.size()) {
    const std::size_t end = std::min(words.find('|', begin), words.size());
    if (haystack.find(lowerCase(words.substr(begin, end - begin))) != std::string::npos) {
      return true;
    }
    begin = end + 1;
  }
  return false;
}

/// Success when `status` has `code` and its message contains every entry of `words` (each entry
/// may list alternatives separated by '|', e.g. "NaN|non-finite"). The message is recorded as a
/// test property, so the XML report shows what users see.
inline ::testing::AssertionResult hasCodeAndWords(const Status& status, StatusCode code,
                                                  std::initializer_list<std::string> words) {
  if (status.ok()) return ::testing::AssertionFailure() << "succeeded, expected a failure";
  ::testing::Test::RecordProperty("message", status.message());
  if (status.code() != code) {
    return ::testing::AssertionFailure()
           << "code " << statusCodeName(status.code()) << ", expected " << statusCodeName(code)
           << ": " << status.message();
  }
  for (const std::string& word : words) {
    if (!containsAnyOf(status.message(), word)) {
      return ::testing::AssertionFailure()
             << "message lacks \"" << word << "\": " << status.message();
    }
  }
  return ::testing::AssertionSuccess();
}

/// As above, for a Result that must have failed.
template <typename T>
::testing::AssertionResult hasCodeAndWords(const Result<T>& result, StatusCode code,
                                           std::initializer_list<std::string> words) {
  if (result.ok()) return ::testing::AssertionFailure() << "succeeded, expected a failure";
  return hasCodeAndWords(result.status(), code, words);
}

/// kInvalidArgument with every word: the usual verdict on bad input.
template <typename T>
::testing::AssertionResult rejected(const T& outcome, std::initializer_list<std::string> words) {
  return hasCodeAndWords(outcome, StatusCode::kInvalidArgument, words);
}

}  // namespace collido::test
