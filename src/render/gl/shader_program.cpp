#include "render/gl/shader_program.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "render/gl/gl.hpp"

namespace sl {

const char* embeddedShader(const char* name);  // generated: cmake/EmbedFiles.cmake

namespace {

// The shaders are compiled into the program (cmake/EmbedFiles.cmake); a folder, when given, is read instead.
std::string readText(const std::string& name, const std::string& folder) {
  if (!folder.empty()) {
    const std::string path = folder + "/" + name;
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read shader " + path + " (the shader folder given)");
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

GLuint compile(GLenum kind, const std::vector<std::string>& paths, const std::string& folder) {
  std::string source;
  for (const auto& path : paths) source += readText(path, folder) + "\n";
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
                             const std::vector<std::string>& fragmentFiles, const std::string& folder) {
  GLuint vertex = compile(GL_VERTEX_SHADER, vertexFiles, folder);
  GLuint fragment = compile(GL_FRAGMENT_SHADER, fragmentFiles, folder);
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

}  // namespace sl
