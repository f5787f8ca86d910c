// Relights a glTF written by vtkRadiosityGLTFWriter in the browser: each light's
// unit-emission solution (a vertex attribute in the file) goes into one float texture, and
// the vertex shader sums them with the color, intensity and on/off of the controls (a
// second texture), then applies the exposure and sRGB encoding per vertex, as the relight
// filter's DisplayColors. Textures, not attributes: WebGL has 16 attributes, not 16 lights.
import * as THREE from "three";
import { GLTFLoader } from "three/examples/jsm/loaders/GLTFLoader.js";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";

const TEXTURE_WIDTH = 4096; // WebGL 2 guarantees textures this wide

function decodeBase64(text) {
  const bytes = atob(text);
  const out = new Uint8Array(bytes.length);
  for (let i = 0; i < bytes.length; ++i) out[i] = bytes.charCodeAt(i);
  return out.buffer;
}

const vertexShader = `uniform highp sampler2D solutions;
uniform highp sampler2D weights;
uniform int lightCount;
uniform float exposure;
out vec3 shade;
vec3 encode(vec3 c) {
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}
void main() {
  vec3 b = vec3(0.0);
  for (int i = 0; i < lightCount; ++i) {
    int t = gl_VertexID * lightCount + i; // light i of this vertex
    b += texelFetch(weights, ivec2(i, 0), 0).rgb * texelFetch(solutions, ivec2(t % ${TEXTURE_WIDTH}, t / ${TEXTURE_WIDTH}), 0).rgb;
  }
  shade = encode(clamp(b * exposure, 0.0, 1.0));
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}`;

/// A float RGBA texture of `texels` texels, TEXTURE_WIDTH wide, filled by `fill(data)`.
function floatTexture(texels, width, fill) {
  const height = Math.max(1, Math.ceil(texels / width));
  const data = new Float32Array(width * height * 4);
  fill(data);
  const texture = new THREE.DataTexture(data, width, height, THREE.RGBAFormat, THREE.FloatType);
  texture.minFilter = texture.magFilter = THREE.NearestFilter;
  texture.needsUpdate = true;
  return texture;
}

/// Every light's solution at every vertex, vertex-major: texel vertex * k + light.
function solutionTexture(geometry, lights) {
  const attributes = lights.map((light) => geometry.getAttribute(light.attribute.toLowerCase()));
  const vertices = geometry.getAttribute("position").count;
  return floatTexture(vertices * lights.length, TEXTURE_WIDTH, (data) => {
    for (let v = 0; v < vertices; ++v) {
      attributes.forEach((a, i) => {
        const t = 4 * (v * lights.length + i);
        data[t] = a.getX(v);
        data[t + 1] = a.getY(v);
        data[t + 2] = a.getZ(v);
      });
    }
  });
}

const fragmentShader = `in vec3 shade;
out vec4 color;
void main() { color = vec4(shade, 1.0); }`;

/// A light's default color split into a displayable color and an intensity.
function splitColor(rgb) {
  const peak = Math.max(rgb[0], rgb[1], rgb[2]);
  if (!(peak > 0)) return { hex: "#ffffff", intensity: 0 }; // a light with no default color: white, off
  const hex = rgb.map((c) => Math.round((255 * c) / peak).toString(16).padStart(2, "0")).join("");
  return { hex: `#${hex}`, intensity: peak };
}

function hexToRgb(hex) {
  return [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16) / 255);
}

/// A number box beside a slider, for values past the slider's end: typing one moves the
/// end out (the slider only offers up to a few times the default).
function numberBeside(slider, onChange) {
  const box = document.createElement("input");
  box.type = "number";
  box.min = "0";
  box.step = "any";
  box.className = "amount";
  const show = () => {
    box.value = String(Number(Number(slider.value).toPrecision(4))); // 0.9, not 0.8999999761581421
  };
  show();
  slider.addEventListener("input", show);
  slider.step = "any"; // a typed value is kept as it is, not snapped to the slider's steps
  box.addEventListener("input", () => {
    const wanted = Number(box.value);
    if (box.value.trim() === "" || !(wanted >= 0)) return; // cleared while retyping: no change yet
    if (wanted > Number(slider.max)) slider.max = String(2 * wanted);
    slider.value = String(wanted);
    onChange();
  });
  slider.after(box);
  return box;
}

function controlRow(light, onChange) {
  const row = document.createElement("div");
  row.className = "light";
  // The relight filter's settings where the file has them, else the light's default.
  const { hex, intensity } = splitColor(light.color || light.defaultColor);
  row.innerHTML = `<label><input type="checkbox"${light.enabled === false ? "" : " checked"}> <span></span></label>
    <input type="color" value="${hex}">
    <input type="range" min="0" max="${4 * (intensity || 1)}" step="${(intensity || 1) / 100}" value="${intensity}">`;
  row.querySelector("span").textContent = light.name;
  const [enabled, color, slider] = row.querySelectorAll("input");
  const weight = () => {
    const rgb = hexToRgb(color.value);
    const on = enabled.checked ? Number(slider.value) : 0;
    return new THREE.Vector3(rgb[0] * on, rgb[1] * on, rgb[2] * on);
  };
  for (const input of [enabled, color, slider]) input.addEventListener("input", onChange);
  numberBeside(slider, onChange);
  return { row, weight, enabled, color, slider };
}

/// A light scene as the relight filter resolved it (relight.export_viewer's `scenes`): each
/// light's color times intensity and on/off, set in its controls as a user would.
function applyScene(controls, scene) {
  scene.lights.forEach((light, i) => {
    if (!controls[i]) return;
    const { hex, intensity } = splitColor(light.color);
    if (intensity > Number(controls[i].slider.max)) controls[i].slider.max = String(2 * intensity);
    controls[i].color.value = hex;
    controls[i].slider.value = String(intensity);
    controls[i].enabled.checked = light.enabled;
    controls[i].slider.dispatchEvent(new Event("input"));
  });
}

/// The scene chooser, shown where the page was exported with light scenes; its first entry
/// puts back the settings the page was exported with.
function sceneChooser(controls, lights) {
  const scenes = window.RELIGHT_SCENES || [];
  const chooser = document.getElementById("scene");
  if (!chooser || scenes.length === 0) return;
  document.getElementById("scenes").hidden = false;
  for (const scene of scenes) {
    const option = document.createElement("option");
    option.textContent = scene.name;
    chooser.appendChild(option);
  }
  const exported = { lights: lights.map((l) => ({ color: l.color || l.defaultColor, enabled: l.enabled !== false })) };
  chooser.addEventListener("change", () => {
    applyScene(controls, scenes.find((s) => s.name === chooser.value) || exported);
  });
}

/// URL settings, as a user's changes: ?scene=Evening&intensity.Amber=4&enabled.Warm%20White=0&color.X=ff0000
/// (the scene first, the lights' own settings over it).
function applyQuery(controls, lights) {
  const query = new URLSearchParams(location.search);
  const chooser = document.getElementById("scene");
  if (query.has("scene") && chooser) {
    chooser.value = query.get("scene");
    chooser.dispatchEvent(new Event("change"));
  }
  lights.forEach((light, i) => {
    const set = (input, key, value) => {
      if (query.has(`${key}.${light.name}`)) {
        input[value] = key === "enabled" ? query.get(`${key}.${light.name}`) !== "0" : query.get(`${key}.${light.name}`);
        input.dispatchEvent(new Event("input"));
      }
    };
    const wanted = Number(query.get(`intensity.${light.name}`));
    if (wanted > Number(controls[i].slider.max)) controls[i].slider.max = String(wanted);
    set(controls[i].slider, "intensity", "value");
    set(controls[i].enabled, "enabled", "checked");
    if (query.has(`color.${light.name}`)) {
      controls[i].color.value = `#${query.get(`color.${light.name}`)}`;
      controls[i].color.dispatchEvent(new Event("input"));
    }
  });
  if (query.get("controls") === "0") document.getElementById("panel").style.display = "none";
}

function placeCamera(camera, view, box) {
  if (view) {
    camera.position.set(...view.position);
    camera.up.set(...view.up);
    camera.fov = view.angle;
    camera.lookAt(new THREE.Vector3(...view.focalPoint));
    return new THREE.Vector3(...view.focalPoint);
  }
  const centre = box.getCenter(new THREE.Vector3());
  camera.position.copy(centre).add(new THREE.Vector3(0, 0, 2 * box.getSize(new THREE.Vector3()).length()));
  camera.lookAt(centre);
  return centre;
}

function start(gltf) {
  let mesh = null;
  gltf.scene.traverse((o) => { if (o.isMesh && !mesh) mesh = o; });
  const info = (mesh.userData && mesh.userData.relight) || (mesh.parent && mesh.parent.userData.relight) || { lights: [], exposure: 1 };
  const lights = info.lights;
  const weights = floatTexture(Math.max(lights.length, 1), Math.max(lights.length, 1), () => {});
  const uniforms = {
    solutions: { value: solutionTexture(mesh.geometry, lights) },
    weights: { value: weights },
    lightCount: { value: lights.length },
    exposure: { value: info.exposure },
  };
  mesh.material = new THREE.ShaderMaterial({
    uniforms, vertexShader, fragmentShader, glslVersion: THREE.GLSL3, side: THREE.DoubleSide,
  });

  const canvas = document.getElementById("view");
  if (window.RELIGHT_SIZE) [canvas.width, canvas.height] = window.RELIGHT_SIZE;
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
  renderer.outputColorSpace = THREE.LinearSRGBColorSpace; // the shader encodes, as VTK's DisplayColors
  const scene = new THREE.Scene();
  scene.add(gltf.scene);
  const camera = new THREE.PerspectiveCamera(30, canvas.width / canvas.height, 0.01, 1e4);
  const box = new THREE.Box3().setFromObject(gltf.scene);
  const target = placeCamera(camera, window.RELIGHT_CAMERA, box);
  const size = box.getSize(new THREE.Vector3()).length();
  camera.near = size * 1e-3;
  camera.far = size * 10;
  camera.updateProjectionMatrix();
  const orbit = new OrbitControls(camera, canvas);
  orbit.target.copy(target);
  orbit.update();

  const render = () => {
    controls.forEach((c, i) => {
      const w = c.weight();
      weights.image.data.set([w.x, w.y, w.z, 0], 4 * i);
    });
    weights.needsUpdate = true;
    uniforms.exposure.value = Number(exposure.value);
    renderer.render(scene, camera);
  };
  const panel = document.getElementById("lights");
  const controls = lights.map((light) => controlRow(light, render));
  controls.forEach((c) => panel.appendChild(c.row));
  const exposure = document.getElementById("exposure");
  exposure.max = 8 * info.exposure;
  exposure.step = info.exposure / 100;
  exposure.value = info.exposure;
  exposure.addEventListener("input", render);
  numberBeside(exposure, render);
  orbit.addEventListener("change", render);
  sceneChooser(controls, lights);
  applyQuery(controls, lights);
  render();
  document.body.dataset.ready = "1";
}

new GLTFLoader().parse(decodeBase64(window.RELIGHT_GLB), "", start, (error) => {
  document.getElementById("status").textContent = `Cannot read the scene: ${error.message || error}`;
});
