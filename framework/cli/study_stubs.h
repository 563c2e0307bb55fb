// The stubs a study's renders ran (the student tree). Each was answered by
// its reference -- or, under --isolate, gave its placeholder -- and, since a
// study measures the pictures' error, none is striped. So a study says which
// on the terminal and on its page: nobody should take its curve for their code.
#pragma once

#include <map>
#include <string>

namespace ll::cli {

class StudyStubs {
 public:
  // task id -> what the stub reported (RenderStats::missingTasks of one render)
  void add(const std::map<std::string, std::string>& missing);
  // One line per task on stderr ("lightlab: A6.2 not implemented: ... -- its reference stood in, ...").
  void print() const;
  // A paragraph for the study's page, or "" when no stub ran.
  std::string html() const;

 private:
  std::map<std::string, std::string> stubs_;
};

}  // namespace ll::cli
