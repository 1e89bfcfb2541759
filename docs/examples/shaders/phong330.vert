#version 330 core
// The vertex stage of docs/examples/shaders/phong330.frag (docs/shaders.md):
// world-space position and normal handed on, clip position from one matrix.
uniform mat4 u_model_view_projection;
in vec3 a_position;
in vec3 a_normal;
in vec2 a_uv;
out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;

void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_uv = a_uv;
  gl_Position = u_model_view_projection * vec4(a_position, 1.0);
}
