// SPDX-License-Identifier: MIT
#include "RawRenderer.h"

#include <osgVis/visapi.h>

#define GLFW_INCLUDE_NONE
#include <GL/glcorearb.h>
#include <GLFW/glfw3.h>

#include <glm/gtc/type_ptr.hpp>

#include <string>

namespace osgVis::rawgl
{
namespace
{
// The GL 3.3 entry points this renderer calls, looked up with glfwGetProcAddress once the context
// is current.
#define OSGVIS_RAWGL_FUNCTIONS(X)                                                                                      \
    X(PFNGLATTACHSHADERPROC, glAttachShader)                                                                           \
    X(PFNGLBINDBUFFERPROC, glBindBuffer)                                                                               \
    X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                                                                     \
    X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                                                                   \
    X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                                                                     \
    X(PFNGLBLENDFUNCPROC, glBlendFunc)                                                                                 \
    X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)                                                                     \
    X(PFNGLBUFFERDATAPROC, glBufferData)                                                                               \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)                                                       \
    X(PFNGLCLEARPROC, glClear)                                                                                         \
    X(PFNGLCLEARCOLORPROC, glClearColor)                                                                               \
    X(PFNGLCOMPILESHADERPROC, glCompileShader)                                                                         \
    X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                                                                         \
    X(PFNGLCREATESHADERPROC, glCreateShader)                                                                           \
    X(PFNGLCULLFACEPROC, glCullFace)                                                                                   \
    X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                                                                         \
    X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                                                               \
    X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                                                                         \
    X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)                                                             \
    X(PFNGLDELETESHADERPROC, glDeleteShader)                                                                           \
    X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                                                               \
    X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                                                                 \
    X(PFNGLDISABLEPROC, glDisable)                                                                                     \
    X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                                                               \
    X(PFNGLENABLEPROC, glEnable)                                                                                       \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)                                                     \
    X(PFNGLFINISHPROC, glFinish)                                                                                       \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)                                                     \
    X(PFNGLFRONTFACEPROC, glFrontFace)                                                                                 \
    X(PFNGLGENBUFFERSPROC, glGenBuffers)                                                                               \
    X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                                                                     \
    X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                                                                   \
    X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                                                                     \
    X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                                                                 \
    X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                                                           \
    X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                                                                   \
    X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                                                             \
    X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                                                               \
    X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                                                             \
    X(PFNGLPIXELSTOREIPROC, glPixelStorei)                                                                             \
    X(PFNGLREADBUFFERPROC, glReadBuffer)                                                                               \
    X(PFNGLREADPIXELSPROC, glReadPixels)                                                                               \
    X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)                                                             \
    X(PFNGLSHADERSOURCEPROC, glShaderSource)                                                                           \
    X(PFNGLUNIFORM1IPROC, glUniform1i)                                                                                 \
    X(PFNGLUNIFORM4FVPROC, glUniform4fv)                                                                               \
    X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                                                                   \
    X(PFNGLUSEPROGRAMPROC, glUseProgram)                                                                               \
    X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)                                                             \
    X(PFNGLVIEWPORTPROC, glViewport)

struct Gl
{
#define OSGVIS_RAWGL_DECLARE(type, name) type name = nullptr;
    OSGVIS_RAWGL_FUNCTIONS(OSGVIS_RAWGL_DECLARE)
#undef OSGVIS_RAWGL_DECLARE

    void load()
    {
#define OSGVIS_RAWGL_LOAD(type, name)                                                                                  \
    name = reinterpret_cast<type>(glfwGetProcAddress(#name));                                                          \
    if (!name)                                                                                                         \
        throw GlError("the GL context has no " #name);
        OSGVIS_RAWGL_FUNCTIONS(OSGVIS_RAWGL_LOAD)
#undef OSGVIS_RAWGL_LOAD
    }
};

const char* const VertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 modelViewProjection;
uniform mat4 modelView;
out vec3 eyeNormal;
void main()
{
    gl_Position = modelViewProjection * vec4(position, 1.0);
    eyeNormal = mat3(modelView) * normal;
}
)";

const char* const FragmentShader = R"(#version 330 core
in vec3 eyeNormal;
uniform vec4 color;
uniform int lit;
out vec4 fragColor;
void main()
{
    float light = 1.0;
    if (lit != 0)
        light = length(eyeNormal) > 0.0 ? 0.25 + 0.75 * abs(normalize(eyeNormal).z) : 0.25;
    fragColor = vec4(color.rgb * light, color.a);
}
)";

std::string lastGlfwError;

void onGlfwError(int, const char* description)
{
    lastGlfwError = description ? description : "";
}

GLenum glMode(Topology topology)
{
    switch (topology)
    {
    case Topology::Lines:
        return GL_LINES;
    case Topology::LineStrip:
        return GL_LINE_STRIP;
    case Topology::LineLoop:
        return GL_LINE_LOOP;
    case Topology::Points:
        return GL_POINTS;
    default:
        return GL_TRIANGLES;
    }
}
} // namespace

struct RawRenderer::Impl
{
    struct Mesh
    {
        GLuint vertexArray = 0, buffer = 0;
        GLsizei vertices = 0;
        GLenum mode = GL_TRIANGLES;
        bool lit = true, cullBack = false, blend = false;
        glm::dmat4 world{1.0};
        float color[4] = {1, 1, 1, 1};
    };

    GLFWwindow* window = nullptr;
    Gl gl;
    unsigned width = 0, height = 0;
    bool show = false;
    GLuint framebuffer = 0, colorBuffer = 0, depthBuffer = 0, program = 0;
    GLint modelViewProjection = -1, modelView = -1, color = -1, lit = -1;
    std::vector<Mesh> meshes;

    // A shader's compile or a program's link status (each has its own GL query and log); throws
    // `failure` followed by the log when it failed.
    static void checkStatus(GLuint object, GLenum status, PFNGLGETSHADERIVPROC getStatus,
                            PFNGLGETSHADERINFOLOGPROC getLog, const char* failure)
    {
        GLint ok = 0;
        getStatus(object, status, &ok);
        if (!ok)
        {
            char log[2048] = {0};
            getLog(object, sizeof log, nullptr, log);
            throw GlError(failure + std::string(log));
        }
    }

    GLuint compile(GLenum type, const char* source)
    {
        const GLuint shader = gl.glCreateShader(type);
        gl.glShaderSource(shader, 1, &source, nullptr);
        gl.glCompileShader(shader);
        checkStatus(shader, GL_COMPILE_STATUS, gl.glGetShaderiv, gl.glGetShaderInfoLog, "shader does not compile: ");
        return shader;
    }

    void makeProgram()
    {
        const GLuint vertex = compile(GL_VERTEX_SHADER, VertexShader);
        const GLuint fragment = compile(GL_FRAGMENT_SHADER, FragmentShader);
        program = gl.glCreateProgram();
        gl.glAttachShader(program, vertex);
        gl.glAttachShader(program, fragment);
        gl.glLinkProgram(program);
        gl.glDeleteShader(vertex);
        gl.glDeleteShader(fragment);
        checkStatus(program, GL_LINK_STATUS, gl.glGetProgramiv, gl.glGetProgramInfoLog, "program does not link: ");
        modelViewProjection = gl.glGetUniformLocation(program, "modelViewProjection");
        modelView = gl.glGetUniformLocation(program, "modelView");
        color = gl.glGetUniformLocation(program, "color");
        lit = gl.glGetUniformLocation(program, "lit");
    }

    void makeFramebuffer()
    {
        gl.glGenFramebuffers(1, &framebuffer);
        gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        gl.glGenRenderbuffers(1, &colorBuffer);
        gl.glBindRenderbuffer(GL_RENDERBUFFER, colorBuffer);
        gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, GLsizei(width), GLsizei(height));
        gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colorBuffer);
        gl.glGenRenderbuffers(1, &depthBuffer);
        gl.glBindRenderbuffer(GL_RENDERBUFFER, depthBuffer);
        gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, GLsizei(width), GLsizei(height));
        gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depthBuffer);
        if (gl.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw GlError("the off-screen framebuffer (" + std::to_string(width) + "x" + std::to_string(height) +
                          ") is incomplete");
    }

    void upload(const RawObject& object)
    {
        Mesh mesh;
        mesh.mode = glMode(object.topology);
        mesh.lit = object.topology == Topology::Triangles;
        mesh.cullBack = (object.flags & OSGVIS_OBJECT_CULL_BACK) != 0;
        mesh.blend = (object.flags & OSGVIS_OBJECT_TRANSPARENT) != 0;
        mesh.world = glm::make_mat4(object.world.data());
        std::copy(object.color, object.color + 4, mesh.color);
        const std::size_t corners = object.positions.size() / 3;
        mesh.vertices = GLsizei(corners);
        std::vector<float> interleaved(6 * corners, 0.0f);
        for (std::size_t i = 0; i < corners; ++i)
            for (int c = 0; c < 3; ++c)
            {
                interleaved[6 * i + std::size_t(c)] = object.positions[3 * i + std::size_t(c)];
                if (!object.normals.empty())
                    interleaved[6 * i + 3 + std::size_t(c)] = object.normals[3 * i + std::size_t(c)];
            }
        gl.glGenVertexArrays(1, &mesh.vertexArray);
        gl.glBindVertexArray(mesh.vertexArray);
        gl.glGenBuffers(1, &mesh.buffer);
        gl.glBindBuffer(GL_ARRAY_BUFFER, mesh.buffer);
        gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)), interleaved.data(),
                        GL_STATIC_DRAW);
        gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
        gl.glEnableVertexAttribArray(0);
        gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                                 reinterpret_cast<const void*>(3 * sizeof(float)));
        gl.glEnableVertexAttribArray(1);
        gl.glBindVertexArray(0);
        meshes.push_back(mesh);
    }
};

RawRenderer::RawRenderer(const RawScene& scene, unsigned width, unsigned height, bool show)
    : _impl(std::make_unique<Impl>())
{
    Impl& m = *_impl;
    m.width = width;
    m.height = height;
    m.show = show;
    glfwSetErrorCallback(&onGlfwError);
    if (!glfwInit())
        throw GlError("GLFW cannot start (" + lastGlfwError + "); is there an X display? (scripts/with-display.sh)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, show ? GLFW_TRUE : GLFW_FALSE);
    m.window = glfwCreateWindow(int(width), int(height), "osgvisrawgl", nullptr, nullptr);
    if (!m.window)
    {
        glfwTerminate();
        throw GlError("cannot open an OpenGL 3.3 core window (" + lastGlfwError + ")");
    }
    glfwMakeContextCurrent(m.window);
    glfwSwapInterval(0);
    m.gl.load();
    m.makeProgram();
    m.makeFramebuffer();
    for (const RawObject& object : scene.objects)
        m.upload(object);
}

RawRenderer::~RawRenderer()
{
    Impl& m = *_impl;
    if (!m.window)
        return;
    for (Impl::Mesh& mesh : m.meshes)
    {
        m.gl.glDeleteBuffers(1, &mesh.buffer);
        m.gl.glDeleteVertexArrays(1, &mesh.vertexArray);
    }
    m.gl.glDeleteRenderbuffers(1, &m.colorBuffer);
    m.gl.glDeleteRenderbuffers(1, &m.depthBuffer);
    m.gl.glDeleteFramebuffers(1, &m.framebuffer);
    m.gl.glDeleteProgram(m.program);
    glfwDestroyWindow(m.window);
    glfwTerminate();
}

void RawRenderer::render(const glm::dmat4& view, const glm::dmat4& projection, const std::vector<bool>& drawn)
{
    Impl& m = *_impl;
    const Gl& gl = m.gl;
    gl.glBindFramebuffer(GL_FRAMEBUFFER, m.framebuffer);
    gl.glViewport(0, 0, GLsizei(m.width), GLsizei(m.height));
    gl.glClearColor(ClearColor[0] / 255.0f, ClearColor[1] / 255.0f, ClearColor[2] / 255.0f, ClearColor[3] / 255.0f);
    gl.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.glEnable(GL_DEPTH_TEST);
    gl.glDepthFunc(GL_LESS);
    gl.glFrontFace(GL_CCW);
    gl.glCullFace(GL_BACK);
    gl.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.glUseProgram(m.program);
    for (std::size_t i = 0; i < m.meshes.size(); ++i)
    {
        const Impl::Mesh& mesh = m.meshes[i];
        if ((!drawn.empty() && !drawn[i]) || mesh.vertices == 0)
            continue;
        // note: composed in double, handed to GL in float.
        const glm::dmat4 modelView = view * mesh.world;
        const glm::mat4 mv(modelView), mvp(projection * modelView);
        gl.glUniformMatrix4fv(m.modelViewProjection, 1, GL_FALSE, glm::value_ptr(mvp));
        gl.glUniformMatrix4fv(m.modelView, 1, GL_FALSE, glm::value_ptr(mv));
        gl.glUniform4fv(m.color, 1, mesh.color);
        gl.glUniform1i(m.lit, mesh.lit ? 1 : 0);
        if (mesh.cullBack)
            gl.glEnable(GL_CULL_FACE);
        else
            gl.glDisable(GL_CULL_FACE);
        if (mesh.blend)
            gl.glEnable(GL_BLEND);
        else
            gl.glDisable(GL_BLEND);
        gl.glBindVertexArray(mesh.vertexArray);
        gl.glDrawArrays(mesh.mode, 0, mesh.vertices);
    }
    gl.glBindVertexArray(0);
    if (m.show)
    {
        int w = 0, h = 0;
        glfwGetFramebufferSize(m.window, &w, &h);
        gl.glBindFramebuffer(GL_READ_FRAMEBUFFER, m.framebuffer);
        gl.glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        gl.glBlitFramebuffer(0, 0, GLint(m.width), GLint(m.height), 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
        glfwSwapBuffers(m.window);
        glfwPollEvents();
    }
    gl.glFinish();
}

void RawRenderer::readPixels(std::vector<std::uint8_t>& rgba)
{
    Impl& m = *_impl;
    rgba.resize(std::size_t(m.width) * m.height * 4);
    m.gl.glBindFramebuffer(GL_READ_FRAMEBUFFER, m.framebuffer);
    m.gl.glReadBuffer(GL_COLOR_ATTACHMENT0);
    m.gl.glPixelStorei(GL_PACK_ALIGNMENT, 1);
    m.gl.glReadPixels(0, 0, GLsizei(m.width), GLsizei(m.height), GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
}

bool RawRenderer::open() const
{
    return !_impl->show || !glfwWindowShouldClose(_impl->window);
}
} // namespace osgVis::rawgl
