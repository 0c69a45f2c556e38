/* Mesa's verdict on corpus programs: compile + link each program directory's stage files
 * (.vert .frag .geom .tesc .tese .comp, in name order) with the OpenGL driver through EGL
 * surfaceless, one 4.5 compatibility-profile context for the whole run.
 *
 * Build:  gcc -O2 -o /tmp/gl_verdict scripts/corpus/gl_verdict.c -lEGL -lGL
 * Run:    /tmp/gl_verdict DIR...        (or one DIR per line on stdin)
 * Output: one line per program, flushed at once:  <dir>\t<ok|fail|na>\t<first error line>
 *   na   = Vulkan-dialect GLSL (layout set=/push_constant/input_attachment_index,
 *          gl_VertexIndex, gl_InstanceIndex, subpassInput): not GL, not compiled.
 * The environment gets EGL_PLATFORM=surfaceless, MESA_GL_VERSION_OVERRIDE=4.6COMPAT and
 * MESA_GLSL_VERSION_OVERRIDE=460 (so `#version 460` compiles) unless already set.
 * A crash in the driver ends the process: scripts/corpus_verdicts.sh runs it per chunk and
 * resumes after the last line printed (a program still compiling after 120 s is killed by
 * SIGALRM the same way). Exit status: 0, or 2 when EGL/GL set-up fails. */
#define _GNU_SOURCE
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <ctype.h>
#include <unistd.h>

static PFNGLCREATESHADERPROC CreateShader;
static PFNGLSHADERSOURCEPROC ShaderSource;
static PFNGLCOMPILESHADERPROC CompileShader;
static PFNGLGETSHADERIVPROC GetShaderiv;
static PFNGLGETSHADERINFOLOGPROC GetShaderInfoLog;
static PFNGLDELETESHADERPROC DeleteShader;
static PFNGLCREATEPROGRAMPROC CreateProgram;
static PFNGLATTACHSHADERPROC AttachShader;
static PFNGLLINKPROGRAMPROC LinkProgram;
static PFNGLGETPROGRAMIVPROC GetProgramiv;
static PFNGLGETPROGRAMINFOLOGPROC GetProgramInfoLog;
static PFNGLDELETEPROGRAMPROC DeleteProgram;

static const struct { const char *ext; GLenum type; } STAGES[] = {
    {".vert", GL_VERTEX_SHADER}, {".frag", GL_FRAGMENT_SHADER}, {".geom", GL_GEOMETRY_SHADER},
    {".tesc", GL_TESS_CONTROL_SHADER}, {".tese", GL_TESS_EVALUATION_SHADER},
    {".comp", GL_COMPUTE_SHADER}};

static GLenum stage_of(const char *name) {
    size_t n = strlen(name);
    for (size_t i = 0; i < sizeof STAGES / sizeof *STAGES; i++) {
        size_t e = strlen(STAGES[i].ext);
        if (n > e && strcmp(name + n - e, STAGES[i].ext) == 0) return STAGES[i].type;
    }
    return 0;
}

static char *slurp(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    size_t cap = 1 << 16, len = 0, r;
    char *buf = malloc(cap + 1);
    while ((r = fread(buf + len, 1, cap - len, f)) > 0) {
        len += r;
        if (len == cap) buf = realloc(buf, (cap *= 2) + 1);
    }
    fclose(f);
    buf[len] = 0;
    return buf;
}

/* Vulkan GLSL: a layout(...) naming set=, push_constant or input_attachment_index, or a
 * Vulkan-only built-in. Comments are not skipped (good enough for a marker). */
static int is_vulkan(const char *s) {
    if (strstr(s, "gl_VertexIndex") || strstr(s, "gl_InstanceIndex") || strstr(s, "subpassInput"))
        return 1;
    for (const char *p = s; (p = strstr(p, "layout")); p += 6) {
        const char *q = p + 6;
        while (isspace((unsigned char)*q)) q++;
        if (*q != '(') continue;
        const char *end = strchr(q, ')');
        if (!end) break;
        for (const char *t = q + 1; t < end; t++) {
            if (isalnum((unsigned char)t[-1]) || t[-1] == '_') continue;
            if (!strncmp(t, "push_constant", 13) || !strncmp(t, "input_attachment_index", 22)) return 1;
            if (!strncmp(t, "set", 3) && !(isalnum((unsigned char)t[3]) || t[3] == '_')) {
                const char *u = t + 3;
                while (isspace((unsigned char)*u)) u++;
                if (*u == '=') return 1;
            }
        }
    }
    return 0;
}

/* First line of an info log that mentions an error, else its first non-empty line. */
static void first_error(const char *log, char *out, size_t cap) {
    const char *pick = NULL, *first = NULL;
    for (const char *l = log; l && *l;) {
        const char *nl = strchr(l, '\n');
        size_t n = nl ? (size_t)(nl - l) : strlen(l);
        if (n && !first) first = l;
        char line[1024];
        snprintf(line, sizeof line, "%.*s", (int)(n < 1000 ? n : 1000), l);
        if (!pick && (strstr(line, "error") || strstr(line, "ERROR"))) pick = l;
        l = nl ? nl + 1 : NULL;
    }
    if (!pick) pick = first;
    if (!pick) { snprintf(out, cap, "(empty info log)"); return; }
    size_t n = strcspn(pick, "\n");
    snprintf(out, cap, "%.*s", (int)(n < cap - 1 ? n : cap - 1), pick);
    for (char *c = out; *c; c++) if (*c == '\t' || *c == '\r') *c = ' ';
}

static int cmpstr(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static void verdict(const char *dir) {
    char *names[64];
    int n = 0;
    alarm(120); /* a compile that hangs ends the process; the wrapper resumes after it */
    DIR *d = opendir(dir);
    if (!d) { printf("%s\tfail\tcannot open directory\n", dir); fflush(stdout); return; }
    struct dirent *e;
    while ((e = readdir(d)) && n < 64)
        if (e->d_name[0] != '.' && stage_of(e->d_name)) names[n++] = strdup(e->d_name);
    closedir(d);
    qsort(names, n, sizeof *names, cmpstr);
    char *texts[64];
    int vk = 0;
    for (int i = 0; i < n; i++) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        texts[i] = slurp(path);
        if (!texts[i]) texts[i] = strdup("");
        vk |= is_vulkan(texts[i]);
    }
    char msg[1024] = "";
    const char *res = "ok";
    if (n == 0) { res = "fail"; snprintf(msg, sizeof msg, "no stage files"); }
    else if (vk) { res = "na"; snprintf(msg, sizeof msg, "Vulkan GLSL"); }
    else {
        GLuint prog = CreateProgram(), sh[64];
        int ns = 0;
        for (int i = 0; i < n; i++) {
            GLuint s = CreateShader(stage_of(names[i]));
            const GLchar *src = texts[i];
            ShaderSource(s, 1, &src, NULL);
            CompileShader(s);
            GLint ok = 0, len = 0;
            GetShaderiv(s, GL_COMPILE_STATUS, &ok);
            sh[ns++] = s;
            if (!ok) {
                GetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
                char *log = calloc(len + 2, 1), first[900];
                GetShaderInfoLog(s, len + 1, NULL, log);
                first_error(log, first, sizeof first);
                free(log);
                res = "fail";
                snprintf(msg, sizeof msg, "%s: %s", names[i], first);
                break;
            }
            AttachShader(prog, s);
        }
        if (!strcmp(res, "ok")) {
            LinkProgram(prog);
            GLint ok = 0, len = 0;
            GetProgramiv(prog, GL_LINK_STATUS, &ok);
            if (!ok) {
                GetProgramiv(prog, GL_INFO_LOG_LENGTH, &len);
                char *log = calloc(len + 2, 1), first[900];
                GetProgramInfoLog(prog, len + 1, NULL, log);
                first_error(log, first, sizeof first);
                free(log);
                res = "fail";
                snprintf(msg, sizeof msg, "link: %s", first);
            }
        }
        for (int i = 0; i < ns; i++) DeleteShader(sh[i]);
        DeleteProgram(prog);
    }
    alarm(0);
    printf("%s\t%s\t%s\n", dir, res, msg);
    fflush(stdout);
    for (int i = 0; i < n; i++) { free(names[i]); free(texts[i]); }
}

#define LOAD(var, name) if (!(*(void **)&var = (void *)eglGetProcAddress(name))) { fprintf(stderr, "no %s\n", name); return 2; }

int main(int argc, char **argv) {
    setenv("EGL_PLATFORM", "surfaceless", 0);
    setenv("MESA_GL_VERSION_OVERRIDE", "4.6COMPAT", 0);
    setenv("MESA_GLSL_VERSION_OVERRIDE", "460", 0);
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
    EGLDisplay dpy = EGL_NO_DISPLAY;
    PFNEGLGETPLATFORMDISPLAYEXTPROC gpd = (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (gpd) dpy = gpd(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (dpy == EGL_NO_DISPLAY) dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    EGLint maj, min;
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &maj, &min)) { fprintf(stderr, "eglInitialize failed\n"); return 2; }
    if (!eglBindAPI(EGL_OPENGL_API)) { fprintf(stderr, "eglBindAPI failed\n"); return 2; }
    EGLint cattr[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig cfg = (EGLConfig)0; /* EGL_NO_CONFIG_KHR */
    EGLint ncfg = 0;
    eglChooseConfig(dpy, cattr, &cfg, 1, &ncfg);
    if (ncfg < 1) cfg = (EGLConfig)0;
    EGLint attr[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, attr);
    if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        fprintf(stderr, "no GL 4.5 compatibility context (EGL error 0x%x)\n", eglGetError());
        return 2;
    }
    LOAD(CreateShader, "glCreateShader") LOAD(ShaderSource, "glShaderSource")
    LOAD(CompileShader, "glCompileShader") LOAD(GetShaderiv, "glGetShaderiv")
    LOAD(GetShaderInfoLog, "glGetShaderInfoLog") LOAD(DeleteShader, "glDeleteShader")
    LOAD(CreateProgram, "glCreateProgram") LOAD(AttachShader, "glAttachShader")
    LOAD(LinkProgram, "glLinkProgram") LOAD(GetProgramiv, "glGetProgramiv")
    LOAD(GetProgramInfoLog, "glGetProgramInfoLog") LOAD(DeleteProgram, "glDeleteProgram")
    if (getenv("GL_VERDICT_INFO"))
        fprintf(stderr, "%s | %s\n", glGetString(GL_VERSION), glGetString(GL_RENDERER));
    if (argc > 1) {
        for (int i = 1; i < argc; i++) verdict(argv[i]);
    } else {
        char line[4096];
        while (fgets(line, sizeof line, stdin)) {
            line[strcspn(line, "\r\n")] = 0;
            size_t l = strlen(line);
            while (l > 1 && line[l - 1] == '/') line[--l] = 0;
            if (*line) verdict(line);
        }
    }
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, ctx);
    eglTerminate(dpy);
    return 0;
}
