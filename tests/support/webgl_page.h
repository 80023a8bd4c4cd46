// The WebGL2 plumbing that the browser tests' pages share, as JavaScript to
// put at the top of a page's module script (before code that calls it):
//
//   lutbakeProgram(gl, fragment, units)
//     compiles the full-screen triangle's vertex shader (three vertices from
//     gl_VertexID, covering the viewport) and `fragment` (GLSL ES 3.00
//     source), links and uses them, and points each sampler uniform named in
//     `units` ({name: texture unit}) at its unit; throws an Error holding the
//     compiler's or linker's log.
//   lutbakeDrawPixels(gl, size, unit, float)
//     draws that triangle into a size x size texture bound on texture unit
//     `unit` (one no sampler reads), RGBA32F when `float`, else RGBA8, and
//     returns its pixels as an Array, RGBA, row y = 0 first (RGBA8 as
//     value / 255).
#pragma once

namespace lutbake::test {

inline constexpr const char *kWebGlPageHelpers = R"(
const lutbakeProgram = (gl, fragment, units) => {
  const vertex = `#version 300 es
      void main() { vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
                    gl_Position = vec4(p, 0.0, 1.0); }`;
  const compile = (type, text) => {
    const s = gl.createShader(type);
    gl.shaderSource(s, text);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
    return s;
  };
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl.VERTEX_SHADER, vertex));
  gl.attachShader(program, compile(gl.FRAGMENT_SHADER, fragment));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
  gl.useProgram(program);
  for (const [name, unit] of Object.entries(units))
    gl.uniform1i(gl.getUniformLocation(program, name), unit);
  return program;
};
const lutbakeDrawPixels = (gl, size, unit, float) => {
  const target = gl.createTexture();
  gl.activeTexture(gl.TEXTURE0 + unit);
  gl.bindTexture(gl.TEXTURE_2D, target);
  gl.texStorage2D(gl.TEXTURE_2D, 1, float ? gl.RGBA32F : gl.RGBA8, size, size);
  const fb = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
  gl.viewport(0, 0, size, size);
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  const pixels = float ? new Float32Array(size * size * 4) : new Uint8Array(size * size * 4);
  gl.readPixels(0, 0, size, size, gl.RGBA, float ? gl.FLOAT : gl.UNSIGNED_BYTE, pixels);
  return Array.from(pixels, v => (float ? v : v / 255));
};
)";

}  // namespace lutbake::test
