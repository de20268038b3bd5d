// The page's 3-D view in WebGL2: the heights as a mesh (read from a float texture in the vertex
// shader), coloured by the look's band colours (look::band_colour_map) and lit by its sun, the
// sky dome behind (look::bake_sky_dome), the trees the module places, instanced, and the sea as
// a plane at sea level tinted by depth.
// Orbit with the mouse; walk with the keys, the eye kept above the ground. The view draws what
// the module computed; it computes no terrain or colour of its own.
'use strict';

const SansuiView = (() => {
  let gl = null;
  let canvas = null;
  let world = null;         // facts, heights and GPU objects of the world shown
  let programs = {};
  const camera = { azimuth: 200, elevation: 35, distance: 1.3, walking: false, x: 0.5, z: 0.5, bearing: 0, pitch: 0 };
  const keys = new Set();
  let frameRequested = false;
  let errors = [];          // WebGL errors seen (the tests read them)
  let frames = 0;
  let maxCells = 512;       // mesh cells a side (init() lowers it on a software renderer)
  let treeBudget = 100000;  // trees drawn at most (init() lowers it on a software renderer)
  let treeDelay = 200;      // ms a new world stays unchanged before its trees are placed
  const meshes = {};        // the trees' shapes: cone, crown

  const terrainVs = `#version 300 es
  precision highp float;
  uniform highp sampler2D u_heights;   // metres, one texel per sample
  uniform mat4 u_view_proj;
  uniform vec2 u_extent;               // metres east and south
  uniform float u_exaggeration;
  uniform int u_step;                  // samples between mesh vertices
  uniform int u_columns;               // vertices per mesh row
  out vec2 v_uv;
  out float v_height;
  out vec3 v_position;
  float h(ivec2 p) {
    ivec2 size = textureSize(u_heights, 0);
    return texelFetch(u_heights, clamp(p, ivec2(0), size - 1), 0).r;
  }
  void main() {
    ivec2 size = textureSize(u_heights, 0);
    ivec2 p = min(ivec2(gl_VertexID % u_columns, gl_VertexID / u_columns) * u_step, size - 1);
    float height = h(p);
    vec2 cell = u_extent / vec2(size - 1);
    v_uv = (vec2(p) + 0.5) / vec2(size);
    v_height = height;
    v_position = vec3(vec2(p) * cell, 0.0).xzy + vec3(0.0, height * u_exaggeration, 0.0);
    gl_Position = u_view_proj * vec4(v_position, 1.0);
  }`;

  const shading = `
  uniform vec3 u_sun;          // toward the sun
  uniform vec3 u_sun_colour;   // sRGB
  uniform vec3 u_sky_light;    // sRGB
  uniform vec3 u_camera;
  uniform float u_fog_distance;
  uniform vec3 u_horizon;      // sRGB: the sky's colour at the horizon
  vec3 linear(vec3 c) { return pow(c, vec3(2.2)); }
  vec3 encoded(vec3 c) { return pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)); }
  vec3 fogged(vec3 colour, vec3 position) {
    float fog = 1.0 - exp(-max(distance(position, u_camera) - u_fog_distance, 0.0) / (4.0 * u_fog_distance));
    return mix(colour, linear(u_horizon), clamp(fog, 0.0, 0.7));
  }`;

  const terrainFs = `#version 300 es
  precision highp float;
  uniform sampler2D u_colours;  // sRGB band colours
  uniform highp sampler2D u_heights;
  uniform vec2 u_extent;
  uniform float u_exaggeration;
  ${shading}
  in vec2 v_uv;
  in float v_height;
  in vec3 v_position;
  out vec4 colour;
  float h(ivec2 p) {
    ivec2 size = textureSize(u_heights, 0);
    return texelFetch(u_heights, clamp(p, ivec2(0), size - 1), 0).r;
  }
  void main() {
    vec3 albedo = texture(u_colours, v_uv).rgb;  // an sRGB texture: sampled as linear
    // The normal of every sample, whatever the mesh's spacing: lighting keeps the full detail.
    ivec2 size = textureSize(u_heights, 0);
    ivec2 p = ivec2(v_uv * vec2(size));
    vec2 cell = u_extent / vec2(size - 1);
    float dx = (h(p + ivec2(1, 0)) - h(p - ivec2(1, 0))) / (2.0 * cell.x);
    float dz = (h(p + ivec2(0, 1)) - h(p - ivec2(0, 1))) / (2.0 * cell.y);
    vec3 n = normalize(vec3(-dx * u_exaggeration, 1.0, -dz * u_exaggeration));
    float sun = max(dot(n, u_sun), 0.0) * step(0.0, u_sun.y);
    vec3 light = linear(u_sun_colour) * sun * 2.2 + linear(u_sky_light) * (0.35 + 0.25 * n.y);
    colour = vec4(encoded(fogged(albedo * light, v_position)), 1.0);
  }`;

  const waterVs = `#version 300 es
  precision highp float;
  uniform mat4 u_view_proj;
  uniform vec2 u_extent;
  uniform float u_level;     // drawing units
  out vec2 v_uv;
  out vec3 v_position;
  void main() {
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    v_uv = corner;
    v_position = vec3(corner.x * u_extent.x, u_level, corner.y * u_extent.y);
    gl_Position = u_view_proj * vec4(v_position, 1.0);
  }`;

  const waterFs = `#version 300 es
  precision highp float;
  uniform highp sampler2D u_heights;
  uniform float u_sea_level;   // metres
  uniform vec3 u_shallow, u_deep;
  ${shading}
  in vec2 v_uv;
  in vec3 v_position;
  out vec4 colour;
  void main() {
    float depth = u_sea_level - texture(u_heights, v_uv).r;
    if (depth <= 0.0) discard;
    vec3 water = mix(linear(u_shallow), linear(u_deep), clamp(depth / 40.0, 0.0, 1.0));
    vec3 view = normalize(u_camera - v_position);
    float fresnel = 0.02 + 0.98 * pow(1.0 - max(view.y, 0.0), 5.0);
    vec3 lit = water * (linear(u_sun_colour) * max(u_sun.y, 0.0) * 1.5 + linear(u_sky_light) * 0.5);
    lit = mix(lit, linear(u_horizon), fresnel * 0.6);
    colour = vec4(encoded(fogged(lit, v_position)), clamp(0.6 + depth / 20.0, 0.6, 0.95));
  }`;

  const skyVs = `#version 300 es
  out vec2 v_ndc;
  void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
    v_ndc = p;
    gl_Position = vec4(p, 0.9999, 1.0);
  }`;

  const skyFs = `#version 300 es
  precision highp float;
  uniform mat4 u_inverse_view_proj;
  uniform sampler2D u_sky;       // azimuth across, elevation u_top..u_bottom down
  uniform float u_top, u_bottom;
  in vec2 v_ndc;
  out vec4 colour;
  void main() {
    vec4 far = u_inverse_view_proj * vec4(v_ndc, 1.0, 1.0);
    vec4 near = u_inverse_view_proj * vec4(v_ndc, -1.0, 1.0);
    vec3 dir = normalize(far.xyz / far.w - near.xyz / near.w);
    float azimuth = degrees(atan(dir.x, -dir.z));
    float elevation = degrees(asin(clamp(dir.y, -1.0, 1.0)));
    vec2 uv = vec2(fract(azimuth / 360.0), clamp((u_top - elevation) / (u_top - u_bottom), 0.0, 1.0));
    colour = vec4(texture(u_sky, uv).rgb, 1.0);
  }`;

  // Trees: one low mesh per shape (a cone, a rounded crown) on a trunk, drawn instanced at the
  // module's placements (scene::place_scene_plants), sized by each tree's height and crown.
  const treeVs = `#version 300 es
  precision highp float;
  layout(location = 0) in vec3 a_local;    // x, z in crown radii; y in tree heights
  layout(location = 1) in vec3 a_normal;
  layout(location = 2) in float a_part;    // 0 trunk, 1 crown
  layout(location = 3) in vec3 a_at;       // metres east and south of sample (0, 0), ground height
  layout(location = 4) in vec2 a_size;     // height, crown radius (metres)
  layout(location = 5) in vec3 a_colour;   // the crown's, sRGB
  uniform mat4 u_view_proj;
  uniform float u_exaggeration;
  out vec3 v_normal;
  out vec3 v_colour;
  out vec3 v_position;
  void main() {
    v_position = vec3(a_at.x + a_local.x * a_size.y, a_at.z * u_exaggeration + a_local.y * a_size.x, a_at.y + a_local.z * a_size.y);
    v_normal = a_normal;
    v_colour = a_part < 0.5 ? vec3(0.32, 0.24, 0.17) : a_colour;
    gl_Position = u_view_proj * vec4(v_position, 1.0);
  }`;

  const treeFs = `#version 300 es
  precision highp float;
  ${shading}
  in vec3 v_normal;
  in vec3 v_colour;
  in vec3 v_position;
  out vec4 colour;
  void main() {
    vec3 n = normalize(v_normal);
    float sun = max(dot(n, u_sun), 0.0) * step(0.0, u_sun.y);
    vec3 light = linear(u_sun_colour) * sun * 1.8 + linear(u_sky_light) * (0.3 + 0.2 * n.y);
    colour = vec4(encoded(fogged(linear(v_colour) * light, v_position)), 1.0);
  }`;

  /** A tree's mesh as triangles of (position, normal, part): a trunk, and a cone or a rounded crown. */
  function treeMesh(cone) {
    const out = [];
    const sides = 8;
    const ring = (k, n) => [Math.cos((2 * Math.PI * k) / n), Math.sin((2 * Math.PI * k) / n)];
    const vertex = (p, n, part) => out.push(p[0], p[1], p[2], n[0], n[1], n[2], part);
    // The trunk: four sides, from just below the ground into the crown.
    const trunkTop = cone ? 0.3 : 0.45, trunkRadius = cone ? 0.12 : 0.09;
    for (let k = 0; k < 4; ++k) {
      const [a, b] = [ring(k, 4), ring(k + 1, 4)];
      const n = [(a[0] + b[0]) / 2, 0, (a[1] + b[1]) / 2];
      const low = (c) => [c[0] * trunkRadius, -0.05, c[1] * trunkRadius], high = (c) => [c[0] * trunkRadius, trunkTop, c[1] * trunkRadius];
      for (const p of [low(a), low(b), high(b), low(a), high(b), high(a)]) vertex(p, n, 0);
    }
    // The crown: rings of (height, radius), closed at the bottom and the top.
    const rings = cone ? [[0.2, 0.0], [0.22, 1.0], [1.0, 0.0]] : [[0.3, 0.0], [0.36, 0.6], [0.58, 1.0], [0.84, 0.75], [1.0, 0.0]];
    const normalAt = (c, y, r) => (cone ? [c[0], 0.55, c[1]] : [c[0] * Math.max(r, 0.2), (y - 0.62) * 2.2, c[1] * Math.max(r, 0.2)]);
    for (let j = 0; j + 1 < rings.length; ++j) {
      const [y0, r0] = rings[j], [y1, r1] = rings[j + 1];
      for (let k = 0; k < sides; ++k) {
        const a = ring(k, sides), b = ring(k + 1, sides);
        const p = (c, y, r) => [c[0] * r, y, c[1] * r];
        const tri = [[a, y0, r0], [b, y0, r0], [b, y1, r1], [a, y0, r0], [b, y1, r1], [a, y1, r1]];
        for (const [c, y, r] of tri) vertex(p(c, y, r), normalAt(c, y, r), 1);
      }
    }
    return new Float32Array(out);
  }

  function compile(vs, fs) {
    const program = gl.createProgram();
    for (const [type, source] of [[gl.VERTEX_SHADER, vs], [gl.FRAGMENT_SHADER, fs]]) {
      const shader = gl.createShader(type);
      gl.shaderSource(shader, source);
      gl.compileShader(shader);
      if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(shader));
      gl.attachShader(program, shader);
    }
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
    const uniforms = {};
    const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS);
    for (let k = 0; k < count; ++k) {
      const name = gl.getActiveUniform(program, k).name;
      uniforms[name] = gl.getUniformLocation(program, name);
    }
    return { program, uniforms };
  }

  function texture(unit, internal, format, type, width, height, data, filter) {
    const t = gl.createTexture();
    gl.activeTexture(gl.TEXTURE0 + unit);
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.texImage2D(gl.TEXTURE_2D, 0, internal, width, height, 0, format, type, data);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, filter);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    return t;
  }

  // ---- matrices (column-major, as WebGL takes them) ----
  function perspective(fovy, aspect, near, far) {
    const f = 1 / Math.tan(fovy / 2);
    return [f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) / (near - far), -1, 0, 0, (2 * far * near) / (near - far), 0];
  }
  function lookAt(eye, target) {
    const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    const norm = (a) => { const l = Math.hypot(...a); return a.map((v) => v / l); };
    const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const f = norm(sub(target, eye));
    const s = norm(cross(f, [0, 1, 0]));
    const u = cross(s, f);
    return [s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, -dot(s, eye), -dot(u, eye), dot(f, eye), 1];
  }
  function multiply(a, b) {
    const out = new Array(16).fill(0);
    for (let c = 0; c < 4; ++c) for (let r = 0; r < 4; ++r) for (let k = 0; k < 4; ++k) out[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
    return out;
  }
  function invert(m) {
    const inv = new Array(16);
    const [a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, a30, a31, a32, a33] = m;
    const b00 = a00 * a11 - a01 * a10, b01 = a00 * a12 - a02 * a10, b02 = a00 * a13 - a03 * a10, b03 = a01 * a12 - a02 * a11;
    const b04 = a01 * a13 - a03 * a11, b05 = a02 * a13 - a03 * a12, b06 = a20 * a31 - a21 * a30, b07 = a20 * a32 - a22 * a30;
    const b08 = a20 * a33 - a23 * a30, b09 = a21 * a32 - a22 * a31, b10 = a21 * a33 - a23 * a31, b11 = a22 * a33 - a23 * a32;
    const d = 1 / (b00 * b11 - b01 * b10 + b02 * b09 + b03 * b08 - b04 * b07 + b05 * b06);
    inv[0] = (a11 * b11 - a12 * b10 + a13 * b09) * d; inv[1] = (a02 * b10 - a01 * b11 - a03 * b09) * d;
    inv[2] = (a31 * b05 - a32 * b04 + a33 * b03) * d; inv[3] = (a22 * b04 - a21 * b05 - a23 * b03) * d;
    inv[4] = (a12 * b08 - a10 * b11 - a13 * b07) * d; inv[5] = (a00 * b11 - a02 * b08 + a03 * b07) * d;
    inv[6] = (a32 * b02 - a30 * b05 - a33 * b01) * d; inv[7] = (a20 * b05 - a22 * b02 + a23 * b01) * d;
    inv[8] = (a10 * b10 - a11 * b08 + a13 * b06) * d; inv[9] = (a01 * b08 - a00 * b10 - a03 * b06) * d;
    inv[10] = (a30 * b04 - a31 * b02 + a33 * b00) * d; inv[11] = (a21 * b02 - a20 * b04 - a23 * b00) * d;
    inv[12] = (a11 * b07 - a10 * b09 - a12 * b06) * d; inv[13] = (a00 * b09 - a01 * b07 + a02 * b06) * d;
    inv[14] = (a31 * b01 - a30 * b03 - a32 * b00) * d; inv[15] = (a20 * b03 - a21 * b01 + a22 * b00) * d;
    return inv;
  }

  /** Ground height (drawing units) under a point in 0..1 of the extent, from the heights. */
  function groundAt(u, v) {
    const f = world.facts;
    const x = Math.min(Math.max(u, 0), 1) * (f.width - 1), y = Math.min(Math.max(v, 0), 1) * (f.height - 1);
    const h = world.heights[Math.round(y) * f.width + Math.round(x)];
    return Math.max(h, f.sea ? f.sea_level_m : h) * f.exaggeration;
  }

  function draw() {
    frameRequested = false;
    if (!world) return;
    const f = world.facts;
    const width = canvas.clientWidth || canvas.width, height = canvas.clientHeight || canvas.height;
    if (canvas.width !== width || canvas.height !== height) { canvas.width = width; canvas.height = height; }
    gl.viewport(0, 0, canvas.width, canvas.height);
    const extent = [(f.width - 1) * f.cell_m, (f.height - 1) * f.cell_m];
    const size = Math.max(extent[0], extent[1]);
    let eye, target;
    if (camera.walking) {
      const ground = groundAt(camera.x, camera.z);
      eye = [camera.x * extent[0], ground + 2.0 * f.exaggeration + size * 0.002, camera.z * extent[1]];
      const b = (camera.bearing * Math.PI) / 180, p = (camera.pitch * Math.PI) / 180;
      target = [eye[0] + Math.sin(b) * Math.cos(p), eye[1] + Math.sin(p), eye[2] - Math.cos(b) * Math.cos(p)];
    } else {
      const a = (camera.azimuth * Math.PI) / 180, e = (camera.elevation * Math.PI) / 180;
      const mid = (f.min_m + f.max_m) / 2 * f.exaggeration;
      target = [extent[0] / 2, mid, extent[1] / 2];
      const d = camera.distance * size;
      eye = [target[0] + Math.sin(a) * Math.cos(e) * d, target[1] + Math.sin(e) * d, target[2] - Math.cos(a) * Math.cos(e) * d];
    }
    const viewProj = multiply(perspective(Math.PI / 4, canvas.width / canvas.height, size * 0.0005, size * 8), lookAt(eye, target));
    const horizon = world.horizon;

    gl.disable(gl.DEPTH_TEST);
    gl.useProgram(programs.sky.program);
    gl.uniformMatrix4fv(programs.sky.uniforms.u_inverse_view_proj, false, invert(viewProj));
    gl.uniform1i(programs.sky.uniforms.u_sky, 2);
    gl.uniform1f(programs.sky.uniforms.u_top, f.sky.top_deg);
    gl.uniform1f(programs.sky.uniforms.u_bottom, f.sky.bottom_deg);
    gl.drawArrays(gl.TRIANGLES, 0, 3);

    gl.enable(gl.DEPTH_TEST);
    gl.clear(gl.DEPTH_BUFFER_BIT);
    const common = (p) => {
      gl.useProgram(p.program);
      gl.uniformMatrix4fv(p.uniforms.u_view_proj, false, viewProj);
      gl.uniform2f(p.uniforms.u_extent, extent[0], extent[1]);
      gl.uniform3fv(p.uniforms.u_sun, f.sun.direction);
      gl.uniform3fv(p.uniforms.u_sun_colour, f.sun_colour);
      gl.uniform3fv(p.uniforms.u_sky_light, f.sky_light);
      gl.uniform3fv(p.uniforms.u_camera, eye);
      gl.uniform1f(p.uniforms.u_fog_distance, size);  // haze starts a world's width away
      gl.uniform3fv(p.uniforms.u_horizon, horizon);
      gl.uniform1i(p.uniforms.u_heights, 0);
    };
    const t = programs.terrain;
    common(t);
    gl.uniform1f(t.uniforms.u_exaggeration, f.exaggeration);
    gl.uniform1i(t.uniforms.u_colours, 1);
    gl.uniform1i(t.uniforms.u_step, world.step);
    gl.uniform1i(t.uniforms.u_columns, world.columns);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, world.indices);
    gl.drawElements(gl.TRIANGLES, world.indexCount, gl.UNSIGNED_INT, 0);

    if (world.trees) {
      const tp = programs.tree;
      common(tp);
      gl.uniform1f(tp.uniforms.u_exaggeration, f.exaggeration);
      for (const shape of world.trees.shapes) {
        if (!shape.count) continue;
        gl.bindVertexArray(shape.vao);
        gl.drawArraysInstanced(gl.TRIANGLES, 0, shape.vertices, shape.count);
      }
      gl.bindVertexArray(null);
    }

    if (f.sea) {
      const w = programs.water;
      common(w);
      gl.uniform1f(w.uniforms.u_level, f.sea_level_m * f.exaggeration);
      gl.uniform1f(w.uniforms.u_sea_level, f.sea_level_m);
      gl.uniform3fv(w.uniforms.u_shallow, f.water_shallow);
      gl.uniform3fv(w.uniforms.u_deep, f.water_deep);
      gl.enable(gl.BLEND);
      gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
      gl.drawArrays(gl.TRIANGLE_STRIP, 0, 4);
      gl.disable(gl.BLEND);
    }
    const error = gl.getError();
    if (error !== gl.NO_ERROR) errors.push(error);
    frames++;
  }

  function redraw() {
    if (!frameRequested) {
      frameRequested = true;
      requestAnimationFrame(draw);
    }
  }

  /** Frees the trees' GPU buffers. */
  function dropTrees() {
    if (!world || !world.trees) return;
    for (const shape of world.trees.shapes) {
      gl.deleteVertexArray(shape.vao);
      gl.deleteBuffer(shape.instances);
    }
    world.trees = null;
  }

  /** The trees of the world shown: nine floats each (see web/src/bindings.cpp, Session::plants). */
  function setPlants(plants) {
    if (!world) return;
    dropTrees();
    const per = 9, count = plants.length / per;
    const shapes = [];
    for (const [form, mesh] of [[0, meshes.cone], [1, meshes.crown]]) {
      const chosen = [];
      for (let k = 0; k < count; ++k) if (plants[k * per + 8] === form) chosen.push(...plants.subarray(k * per, k * per + 8));
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      gl.bindBuffer(gl.ARRAY_BUFFER, mesh.buffer);
      gl.enableVertexAttribArray(0); gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 28, 0);
      gl.enableVertexAttribArray(1); gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 28, 12);
      gl.enableVertexAttribArray(2); gl.vertexAttribPointer(2, 1, gl.FLOAT, false, 28, 24);
      const instances = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, instances);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(chosen), gl.STATIC_DRAW);
      for (const [location, size, offset] of [[3, 3, 0], [4, 2, 12], [5, 3, 20]]) {
        gl.enableVertexAttribArray(location);
        gl.vertexAttribPointer(location, size, gl.FLOAT, false, 32, offset);
        gl.vertexAttribDivisor(location, 1);
      }
      gl.bindVertexArray(null);
      shapes.push({ vao, instances, vertices: mesh.vertices, count: chosen.length / 8 });
    }
    world.trees = { shapes, count };
    redraw();
  }

  function setWorld(facts, heights, colours, sky) {
    dropTrees();
    if (world) for (const t of [world.heightsTexture, world.coloursTexture, world.skyTexture]) gl.deleteTexture(t);
    if (world) gl.deleteBuffer(world.indices);
    // At most 513 vertices a side (257 on a software renderer, such as SwiftShader where no GPU
    // is): a 1025 world's mesh takes every other sample. The heights texture keeps every
    // sample, for the per-pixel normals and the water's depth.
    const step = Math.max(1, Math.ceil((facts.width - 1) / maxCells));
    const columns = Math.floor((facts.width - 1) / step) + 1, rows = Math.floor((facts.height - 1) / step) + 1;
    const indices = new Uint32Array((columns - 1) * (rows - 1) * 6);
    let k = 0;
    for (let y = 0; y + 1 < rows; ++y) {
      for (let x = 0; x + 1 < columns; ++x) {
        const i = y * columns + x;
        indices.set([i, i + columns, i + 1, i + 1, i + columns, i + columns + 1], k);
        k += 6;
      }
    }
    const buffer = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, buffer);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
    const horizonRow = Math.round((facts.sky.top_deg / (facts.sky.top_deg - facts.sky.bottom_deg)) * (facts.sky.height - 1));
    const h = 4 * horizonRow * facts.sky.width;
    world = {
      facts, heights, step, columns, indices: buffer, indexCount: indices.length,
      horizon: [sky[h] / 255, sky[h + 1] / 255, sky[h + 2] / 255],
      heightsTexture: texture(0, gl.R32F, gl.RED, gl.FLOAT, facts.width, facts.height, heights, gl.NEAREST),
      coloursTexture: texture(1, gl.SRGB8_ALPHA8, gl.RGBA, gl.UNSIGNED_BYTE, facts.colours.width, facts.colours.height, colours, gl.LINEAR),
      skyTexture: texture(2, gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE, facts.sky.width, facts.sky.height, sky, gl.LINEAR),
    };
    redraw();
  }

  function init(element) {
    canvas = element;
    gl = canvas.getContext('webgl2', { antialias: true, preserveDrawingBuffer: true });
    if (!gl) throw new Error('This browser has no WebGL2');
    programs = {
      terrain: compile(terrainVs, terrainFs), water: compile(waterVs, waterFs), sky: compile(skyVs, skyFs), tree: compile(treeVs, treeFs),
    };
    for (const [name, cone] of [['cone', true], ['crown', false]]) {
      const data = treeMesh(cone);
      const buffer = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
      gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
      meshes[name] = { buffer, vertices: data.length / 7 };
    }
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    const renderer = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
    const software = /swiftshader|llvmpipe|software/i.test(renderer);
    maxCells = software ? 256 : 512;
    // A software renderer (SwiftShader) takes about 0.7 s a frame here, so it draws fewer trees,
    // and only once the world has been left alone for a second.
    treeBudget = software ? 5000 : 100000;
    treeDelay = software ? 1000 : 200;
    let dragging = null;
    canvas.addEventListener('pointerdown', (e) => { dragging = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
    canvas.addEventListener('pointerup', () => { dragging = null; });
    canvas.addEventListener('pointermove', (e) => {
      if (!dragging) return;
      const dx = e.clientX - dragging[0], dy = e.clientY - dragging[1];
      dragging = [e.clientX, e.clientY];
      if (camera.walking) {
        camera.bearing += dx * 0.3;
        camera.pitch = Math.max(-80, Math.min(80, camera.pitch - dy * 0.3));
      } else {
        camera.azimuth += dx * 0.4;
        camera.elevation = Math.max(2, Math.min(89, camera.elevation + dy * 0.3));
      }
      redraw();
    });
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      camera.distance = Math.max(0.2, Math.min(6, camera.distance * Math.exp(e.deltaY * 0.001)));
      redraw();
    }, { passive: false });
    window.addEventListener('keydown', (e) => {
      if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
      if (e.key === 'w' && !camera.walking && !keys.size) { camera.walking = true; camera.x = 0.5; camera.z = 0.5; redraw(); return; }
      if (e.key === 'Escape') { camera.walking = false; redraw(); return; }
      keys.add(e.key);
      walkStep();
    });
    window.addEventListener('keyup', (e) => keys.delete(e.key));
    window.addEventListener('resize', redraw);
  }

  /** One step of walking per key press or repeat: 1/200 of the world forward, turning by 5 degrees. */
  function walkStep() {
    if (!camera.walking || !world) return;
    const b = (camera.bearing * Math.PI) / 180, stride = 0.005;
    if (keys.has('ArrowUp') || keys.has('w')) { camera.x += Math.sin(b) * stride; camera.z -= Math.cos(b) * stride; }
    if (keys.has('ArrowDown') || keys.has('s')) { camera.x -= Math.sin(b) * stride; camera.z += Math.cos(b) * stride; }
    if (keys.has('ArrowLeft') || keys.has('a')) camera.bearing -= 5;
    if (keys.has('ArrowRight') || keys.has('d')) camera.bearing += 5;
    camera.x = Math.min(Math.max(camera.x, 0), 1);
    camera.z = Math.min(Math.max(camera.z, 0), 1);
    redraw();
  }

  return {
    init, setWorld, setPlants, redraw, camera,
    plantBudget: () => treeBudget,
    plantDelay: () => treeDelay,
    treesDrawn: () => (world && world.trees ? world.trees.count : 0),
    errors: () => errors.slice(),
    frames: () => frames,
    draw,
  };
})();
window.SansuiView = SansuiView;
