#include "render/gl/shader_program.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "render/gl/gl.hpp"

namespace sl::render {

const char* embeddedShader(const char* name);  // generated: cmake/EmbedFiles.cmake

namespace {

// The shaders are compiled into the program (cmake/EmbedFiles.cmake); SL_SHADER_DIR, when set, names a
// folder to read them from instead, for work on the shaders without rebuilding.
std::string readText(const std::string& name) {
  if (const char* folder = std::getenv("SL_SHADER_DIR"); folder != nullptr && *folder != '\0') {
    const std::string path = std::string(folder) + "/" + name;
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read shader " + path + " (from SL_SHADER_DIR)");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  const char* text = embeddedShader(name.c_str());
  if (text == nullptr) throw std::runtime_error("no shader named " + name + " is built into the program");
  return text;
}

std::string joined(const std::vector<std::string>& paths) {
  std::string text;
  for (const auto& path : paths) text += path + (&path == &paths.back() ? "" : " + ");
  return text;
}

GLuint compile(GLenum kind, const std::vector<std::string>& paths) {
  std::string source;
  for (const auto& path : paths) source += readText(path) + "\n";
  const std::string path = joined(paths);
  const char* text = source.c_str();
  GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error("shader " + path + " does not compile:\n" + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::vector<std::string>& vertexFiles,
                             const std::vector<std::string>& fragmentFiles) {
  GLuint vertex = compile(GL_VERTEX_SHADER, vertexFiles);
  GLuint fragment = compile(GL_FRAGMENT_SHADER, fragmentFiles);
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetProgramInfoLog(program_, sizeof log, nullptr, log);
    throw std::runtime_error("shaders " + joined(vertexFiles) + " / " + joined(fragmentFiles) + " do not link:\n" +
                             log);
  }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(program_); }

void ShaderProgram::use() const { glUseProgram(program_); }

int ShaderProgram::uniform(const char* name) const { return glGetUniformLocation(program_, name); }

}  // namespace sl::render
