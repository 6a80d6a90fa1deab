#pragma once
// A GLSL program compiled from files of the shaders/ folder (built into the program). Each stage is the
// concatenation of its files (common.glsl first: it holds the #version line and the shared functions, GLSL
// has no include). Compile and link errors name the files. `folder`, when not empty, names a folder to read the
// files from instead (work on the shaders without rebuilding; the command line reads it from SL_SHADER_DIR).

#include <string>
#include <vector>

namespace sl {

class ShaderProgram {
 public:
  ShaderProgram(const std::vector<std::string>& vertexFiles, const std::vector<std::string>& fragmentFiles,
                const std::string& folder = "");
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const;
  int uniform(const char* name) const;  // location, -1 if unused

 private:
  unsigned program_ = 0;
};

}  // namespace sl
