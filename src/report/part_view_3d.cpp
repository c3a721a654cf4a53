#include "report/part_view_3d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "report/deviation_views.hpp"
#include "report/figures.hpp"
#include "report/html.hpp"

#ifndef FURROW_THREE_DIR
#define FURROW_THREE_DIR "/usr/share/javascript/three"
#endif

namespace furrow {

namespace {

constexpr Rgb kSurfaceGrey{200, 200, 200};
// Up to this many points each is a sphere mesh (instanced); beyond, a shaded
// point sprite: 100 000 spheres of ~200 triangles are 20 million triangles,
// too many to orbit smoothly without a fast GPU.
constexpr std::size_t kSphereMeshLimit = 20000;

void append_number(std::string& out, double v, int decimals) {
  if (!std::isfinite(v)) v = 0;  // never NaN in the page
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  out += s;
}

void append_colours(std::string& out, const std::vector<Rgb>& colours) {
  static const char* hex = "0123456789abcdef";
  out += '"';
  for (const Rgb& c : colours)
    for (unsigned char b : c) {
      out += hex[b >> 4];
      out += hex[b & 15];
    }
  out += '"';
}

// A JSON string safe inside <script>: "<" escaped so no "</script>" can occur.
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '<' || c == '>' || c == '&' || u < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string read_file_or_throw(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("the report's 3D view needs three.js, and " + path +
                             " cannot be read: install Debian's libjs-three (scripts/install-deps.sh)");
  std::ostringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  // Inlined in <script>: the text must not close the element early.
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return text;
}

std::string legend_gradient(double range) {
  std::string out = "linear-gradient(to right";
  for (int k = 0; k <= 20; ++k) {
    const Rgb c = diverging_colour(-1.0 + k / 10.0);
    char buf[16];
    std::snprintf(buf, sizeof buf, ",#%02x%02x%02x", c[0], c[1], c[2]);
    out += buf;
  }
  (void)range;
  return out + ")";
}

// The viewer: builds the scene from #view3d-data, draws once, marks the
// section for automated checks; static views when WebGL is missing.
const char* kViewerScript = R"JS(
(function(){
var root=document.getElementById('view3d');
function fallback(why){root.setAttribute('data-view3d','fallback:'+why);root.querySelector('.view3d-live').style.display='none';root.querySelector('.view3d-static').style.display='block';}
try{
var probe=document.createElement('canvas');
if(typeof THREE==='undefined'||!window.WebGLRenderingContext||!(probe.getContext('webgl')||probe.getContext('experimental-webgl'))){fallback('no-webgl');return;}
var data=JSON.parse(document.getElementById('view3d-data').textContent);
var live=root.querySelector('.view3d-live'),holder=root.querySelector('.view3d-canvas');
var width=Math.max(320,Math.min(1000,holder.clientWidth||900)),height=560;
var renderer=new THREE.WebGLRenderer({antialias:true,preserveDrawingBuffer:true});
renderer.setPixelRatio(1);renderer.setSize(width,height);renderer.setClearColor(0xf8f8f8,1);
holder.appendChild(renderer.domElement);
var scene=new THREE.Scene();
var lo=data.bounds.min,hi=data.bounds.max;
var centre=new THREE.Vector3((lo[0]+hi[0])/2,(lo[1]+hi[1])/2,(lo[2]+hi[2])/2);
var size=Math.max(hi[0]-lo[0],hi[1]-lo[1],hi[2]-lo[2],1e-3);
var camera=new THREE.PerspectiveCamera(35,width/height,size/100,size*100);
camera.up.set(0,0,1);
scene.add(new THREE.AmbientLight(0xffffff,0.55));
var sun=new THREE.DirectionalLight(0xffffff,0.6);sun.position.set(0.3,-0.4,1);camera.add(sun);scene.add(camera);
function bytes(hex,n){var a=new Float32Array(n*3);for(var i=0;i<n*3;i++)a[i]=parseInt(hex.substr(2*i,2),16)/255;return a;}
var surfaces=[];
data.faces.forEach(function(f){
  var nv=f.v.length/3,g=new THREE.BufferGeometry();
  g.setAttribute('position',new THREE.BufferAttribute(new Float32Array(f.v),3));
  g.setIndex(f.t);g.computeVertexNormals();
  var grey=new Float32Array(nv*3).fill(200/255),pred=data.prediction?bytes(f.p,nv):grey;
  g.setAttribute('color',new THREE.BufferAttribute(grey.slice(),3));
  var m=new THREE.Mesh(g,new THREE.MeshLambertMaterial({vertexColors:THREE.VertexColors,side:THREE.DoubleSide,polygonOffset:true,polygonOffsetFactor:1,polygonOffsetUnits:1}));
  scene.add(m);surfaces.push({geometry:g,grey:grey,pred:pred});
});
var n=data.points.xyz.length/3;
var shade='float l=0.6+0.4*max(dot(normalize(n),normalize(vec3(0.3,0.4,0.86))),0.0);gl_FragColor=vec4(vColor*l,1.0);';
if(n>0&&n<=data.mesh_limit){
  // Instanced spheres: one sphere mesh, drawn n times in one call.
  var sg=new THREE.SphereBufferGeometry(1,12,8),ig=new THREE.InstancedBufferGeometry();
  ig.setIndex(sg.index);ig.setAttribute('position',sg.attributes.position);ig.setAttribute('normal',sg.attributes.normal);
  ig.setAttribute('offset',new THREE.InstancedBufferAttribute(new Float32Array(data.points.xyz),3));
  ig.setAttribute('icolor',new THREE.InstancedBufferAttribute(bytes(data.points.c,n),3));
  ig.maxInstancedCount=n;ig.instanceCount=n;
  var sm=new THREE.ShaderMaterial({uniforms:{radius:{value:data.radius}},
    vertexShader:'uniform float radius;attribute vec3 offset;attribute vec3 icolor;varying vec3 vColor;varying vec3 vNormal;'+
      'void main(){vColor=icolor;vNormal=normalize(normalMatrix*normal);gl_Position=projectionMatrix*modelViewMatrix*vec4(offset+position*radius,1.0);}',
    fragmentShader:'varying vec3 vColor;varying vec3 vNormal;void main(){vec3 n=vNormal;'+shade+'}'});
  var spheres=new THREE.Mesh(ig,sm);spheres.frustumCulled=false;scene.add(spheres);
}else if(n>0){
  // Many points: each sphere a shaded point sprite (one vertex instead of
  // ~200 triangles), still one draw call, sized with the perspective.
  var pg=new THREE.BufferGeometry();
  pg.setAttribute('position',new THREE.BufferAttribute(new Float32Array(data.points.xyz),3));
  pg.setAttribute('icolor',new THREE.BufferAttribute(bytes(data.points.c,n),3));
  var pm=new THREE.ShaderMaterial({uniforms:{radius:{value:data.radius},scale:{value:height/(2*Math.tan(35*Math.PI/360))}},
    vertexShader:'uniform float radius;uniform float scale;attribute vec3 icolor;varying vec3 vColor;'+
      'void main(){vColor=icolor;vec4 mv=modelViewMatrix*vec4(position,1.0);gl_Position=projectionMatrix*mv;gl_PointSize=max(2.0,2.0*radius*scale/-mv.z);}',
    fragmentShader:'varying vec3 vColor;void main(){vec2 p=gl_PointCoord*2.0-1.0;float r2=dot(p,p);if(r2>1.0)discard;vec3 n=vec3(p.x,-p.y,sqrt(1.0-r2));'+shade+'}'});
  var sprites=new THREE.Points(pg,pm);sprites.frustumCulled=false;scene.add(sprites);
}
// Gouge sites and unexplained overcuts: wire spheres in their status
// colour, each labelled by a sprite of its id.
var marks=new THREE.Group();
(data.markers||[]).forEach(function(m){
  var col=new THREE.Color('#'+m.c);
  var ball=new THREE.Mesh(new THREE.SphereBufferGeometry(m.r,16,12),new THREE.MeshBasicMaterial({color:col,wireframe:true,transparent:true,opacity:0.8}));
  ball.position.set(m.at[0],m.at[1],m.at[2]);marks.add(ball);
  var cv=document.createElement('canvas');cv.width=128;cv.height=48;var cx=cv.getContext('2d');
  cx.font='bold 32px sans-serif';cx.fillStyle='#'+m.c;cx.textBaseline='middle';cx.fillText(m.label,4,24);
  var label=new THREE.Sprite(new THREE.SpriteMaterial({map:new THREE.CanvasTexture(cv),depthTest:false}));
  label.scale.set(size*0.08,size*0.03,1);label.position.set(m.at[0],m.at[1],m.at[2]+m.r+size*0.02);marks.add(label);
});
scene.add(marks);
var controls=new THREE.OrbitControls(camera,renderer.domElement);
function render(){renderer.render(scene,camera);}
function view(dir,up){camera.position.copy(centre).add(new THREE.Vector3(dir[0],dir[1],dir[2]).normalize().multiplyScalar(size*1.8));camera.up.set(up[0],up[1],up[2]);controls.target.copy(centre);camera.lookAt(centre);controls.update();render();}
controls.addEventListener('change',render);
view([0.8,-1.3,1.1],[0,0,1]);controls.saveState();
var views={top:[[0,0,1],[0,1,0]],front:[[0,-1,0],[0,0,1]],side:[[1,0,0],[0,0,1]],iso:[[0.8,-1.3,1.1],[0,0,1]]};
root.querySelectorAll('button[data-view]').forEach(function(b){b.addEventListener('click',function(){var k=b.getAttribute('data-view');if(k==='reset'){controls.reset();render();}else view(views[k][0],views[k][1]);});});
var toggle=root.querySelector('input.view3d-zmap');
if(toggle){toggle.addEventListener('change',function(){surfaces.forEach(function(s){s.geometry.attributes.color.array.set(toggle.checked?s.pred:s.grey);s.geometry.attributes.color.needsUpdate=true;});render();});}
var showMarks=root.querySelector('input.view3d-marks');
if(showMarks){showMarks.addEventListener('change',function(){marks.visible=showMarks.checked;render();});}
live.style.display='block';root.querySelector('.view3d-static').style.display='none';
var t0=performance.now();render();
var gl=renderer.getContext(),px=new Uint8Array(width*height*4),drawn=0;
gl.readPixels(0,0,width,height,gl.RGBA,gl.UNSIGNED_BYTE,px);
var t1=performance.now();render();gl.readPixels(0,0,1,1,gl.RGBA,gl.UNSIGNED_BYTE,new Uint8Array(4));
root.setAttribute('data-view3d-frame-ms',(performance.now()-t1).toFixed(0));
for(var i=0;i<px.length;i+=4){if(Math.abs(px[i]-248)>3||Math.abs(px[i+1]-248)>3||Math.abs(px[i+2]-248)>3)drawn++;}
root.setAttribute('data-view3d','drawn:'+drawn);root.setAttribute('data-view3d-spheres',String(n));root.setAttribute('data-view3d-markers',String((data.markers||[]).length));
}catch(e){root.setAttribute('data-view3d','error:'+e.message);fallback('error');throw e;}
})();
)JS";

}  // namespace

std::string three_js_directory() { return FURROW_THREE_DIR; }

PartView3d part_view_3d(const ComparisonDocument& doc, const Part& part, const Prediction* prediction, int grid) {
  PartView3d v;
  v.has_prediction = prediction != nullptr;
  v.range = std::max(std::fabs(doc.options.tolerance.lower()), std::fabs(doc.options.tolerance.upper()));
  for (const auto& p : doc.points)
    if (p.evaluated && std::isfinite(p.deviation)) v.range = std::max(v.range, std::fabs(p.deviation));
  if (!(v.range > 0)) v.range = 1e-3;
  const DeviationScale scale{v.range};
  Eigen::AlignedBox3d box;
  for (const Face& face : part.faces) {
    PartView3d::FaceMesh mesh;
    mesh.name = face.name();
    const ParameterDomain& d = face.domain();
    std::vector<int> index((grid + 1) * (grid + 1), -1);
    for (int j = 0; j <= grid; ++j)
      for (int i = 0; i <= grid; ++i) {
        const double u = d.u0 + d.width_u() * i / grid, w = d.v0 + d.width_v() * j / grid;
        if (!face.contains(u, w)) continue;
        index[j * (grid + 1) + i] = static_cast<int>(mesh.vertices.size());
        mesh.vertices.push_back(face.surface().point(u, w));
        box.extend(mesh.vertices.back());
        if (prediction) {
          const PredictedError e = prediction->predicted_error_at(face.name(), u, w);
          mesh.predicted.push_back(e.reached() ? scale.colour(e.value) : kSurfaceGrey);
        }
      }
    for (int j = 0; j < grid; ++j)
      for (int i = 0; i < grid; ++i) {
        const int a = index[j * (grid + 1) + i], b = index[j * (grid + 1) + i + 1];
        const int c = index[(j + 1) * (grid + 1) + i], e = index[(j + 1) * (grid + 1) + i + 1];
        if (a >= 0 && b >= 0 && e >= 0) mesh.triangles.push_back({a, b, e});
        if (a >= 0 && e >= 0 && c >= 0) mesh.triangles.push_back({a, e, c});
      }
    v.faces.push_back(std::move(mesh));
  }
  for (const auto& p : doc.points) {
    v.points.push_back(p.foot);
    box.extend(p.foot);
    v.colours.push_back(p.evaluated ? scale.colour(p.deviation) : diverging_colour(std::nan("")));
  }
  const double diagonal = box.isEmpty() ? 1.0 : box.diagonal().norm();
  // Visible at a glance but not merging for a typical plan; denser sets get smaller spheres.
  v.sphere_radius = diagonal * (v.points.size() > 20000 ? 0.0015 : v.points.size() > 2000 ? 0.004 : 0.008);
  if (doc.gouges) {
    // At least a hundredth of the part across, so a site of one cell still shows.
    const double least = 0.01 * diagonal;
    for (const GougeSiteCheck& site : doc.gouges->sites) {
      PartView3d::Marker m{site.id, to_string(site.status), site.centroid, least, status_colour(to_string(site.status))};
      if (site.face_index >= 0 && static_cast<std::size_t>(site.face_index) < part.faces.size()) {
        const Face& face = part.faces[static_cast<std::size_t>(site.face_index)];
        const ParameterDomain& d = face.domain();
        for (int corner = 0; corner < 4; ++corner) {
          const Eigen::Vector2d uv = site.uv_box.corner(static_cast<Eigen::AlignedBox2d::CornerType>(corner));
          const Eigen::Vector3d at = face.surface().point(std::clamp(uv.x(), d.u0, d.u0 + d.width_u()),
                                                          std::clamp(uv.y(), d.v0, d.v0 + d.width_v()));
          m.radius = std::max(m.radius, (at - site.centroid).norm());
        }
      }
      v.markers.push_back(std::move(m));
    }
    for (const OvercutCluster& c : doc.gouges->unexplained)
      v.markers.push_back({c.id, "UNEXPLAINED", c.xyz, std::max(least, 4 * v.sphere_radius),
                           status_colour("UNEXPLAINED")});
  }
  return v;
}

std::string part_view_3d_json(const PartView3d& v) {
  std::string out = "{\"range\":";
  append_number(out, v.range, 6);
  out += ",\"radius\":";
  append_number(out, v.sphere_radius, 4);
  out += std::string(",\"prediction\":") + (v.has_prediction ? "true" : "false");
  out += ",\"mesh_limit\":" + std::to_string(kSphereMeshLimit);
  Eigen::AlignedBox3d box;
  for (const auto& f : v.faces)
    for (const auto& p : f.vertices) box.extend(p);
  for (const auto& p : v.points) box.extend(p);
  if (box.isEmpty()) box.extend(Eigen::Vector3d::Zero());
  out += ",\"bounds\":{\"min\":[";
  for (int k = 0; k < 3; ++k) {
    if (k) out += ',';
    append_number(out, box.min()[k], 3);
  }
  out += "],\"max\":[";
  for (int k = 0; k < 3; ++k) {
    if (k) out += ',';
    append_number(out, box.max()[k], 3);
  }
  out += "]},\"faces\":[";
  for (std::size_t f = 0; f < v.faces.size(); ++f) {
    const PartView3d::FaceMesh& m = v.faces[f];
    out += (f ? ",{" : "{");
    out += "\"name\":" + json_string(m.name) + ",\"v\":[";
    for (std::size_t k = 0; k < m.vertices.size(); ++k)
      for (int c = 0; c < 3; ++c) {
        if (k || c) out += ',';
        append_number(out, m.vertices[k][c], 3);
      }
    out += "],\"t\":[";
    for (std::size_t k = 0; k < m.triangles.size(); ++k)
      for (int c = 0; c < 3; ++c) {
        if (k || c) out += ',';
        out += std::to_string(m.triangles[k][static_cast<std::size_t>(c)]);
      }
    out += "],\"p\":";
    append_colours(out, m.predicted);
    out += "}";
  }
  out += "],\"points\":{\"xyz\":[";
  for (std::size_t k = 0; k < v.points.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      if (k || c) out += ',';
      append_number(out, v.points[k][c], 3);
    }
  out += "],\"c\":";
  append_colours(out, v.colours);
  out += "},\"markers\":[";
  for (std::size_t k = 0; k < v.markers.size(); ++k) {
    const PartView3d::Marker& m = v.markers[k];
    out += (k ? ",{" : "{");
    out += "\"label\":" + json_string(m.label) + ",\"status\":" + json_string(m.status) + ",\"at\":[";
    for (int c = 0; c < 3; ++c) {
      if (c) out += ',';
      append_number(out, m.centre[c], 3);
    }
    out += "],\"r\":";
    append_number(out, m.radius, 3);
    out += ",\"c\":";
    append_colours(out, std::vector<Rgb>(1, m.colour));
    out += "}";
  }
  return out + "]}";
}

ReportFigure part_view_3d_figure(const ComparisonDocument& doc, const Part& part, const Prediction* prediction,
                                 const std::string& points_text, const std::string& static_title) {
  const std::string dir = three_js_directory();
  const std::string three = read_file_or_throw(dir + "/build/three.min.js");
  const std::string orbit = read_file_or_throw(dir + "/examples/js/controls/OrbitControls.js");
  const PartView3d view = part_view_3d(doc, part, prediction);

  // The static views: the fallback without WebGL, and the figure file.
  ReportFigure fig;
  fig.file = "figures/part_views.png";
  fig.section = "view3d";
  fig.title = "3D view";
  fig.caption = "";
  fig.png = deviation_views_png(doc, part, view.range, static_title);
  const std::string static_view =
      html::embedded_png(fig.png, "The measured points on the part in four views", "fig-part_views") + "\n";

  char range_um[32];
  std::snprintf(range_um, sizeof range_um, "%.1f", view.range * 1000);
  std::string html =
      "<section id=\"view3d\" data-view3d=\"static\"><h2>3D view</h2>\n<style>.view3d-canvas canvas{border:1px solid "
      "#ddd;max-width:100%}.view3d-legend .bar{display:inline-block;width:320px;height:12px;border:1px solid "
      "#999;vertical-align:middle}.view3d-tools button{margin-right:4px}@media print{.view3d-live{display:none!important}"
      ".view3d-static{display:block!important}}</style>\n";
  html += "<div class=\"view3d-live\" style=\"display:none\">\n<p class=\"view3d-tools\">";
  for (const char* name : {"iso", "top", "front", "side", "reset"})
    html += std::string("<button type=\"button\" data-view=\"") + name + "\">" + name + "</button> ";
  if (view.has_prediction)
    html += "<label><input type=\"checkbox\" class=\"view3d-zmap\"> predicted error (z-map) on the surface</label>";
  if (!view.markers.empty())
    html += " <label><input type=\"checkbox\" class=\"view3d-marks\" checked> gouge sites and unexplained "
            "overcuts</label>";
  html += "</p>\n<div class=\"view3d-canvas\"></div>\n";
  html += "<p class=\"view3d-legend\"><span>&minus;" + std::string(range_um) +
          " &micro;m</span> <span class=\"bar\" style=\"background:" + legend_gradient(view.range) +
          "\"></span> <span>+" + std::string(range_um) +
          " &micro;m</span></p>\n<p class=\"caption\">The part's faces with " +
          (points_text.empty() ? std::string("every measured point as a sphere at its foot point") : points_text) +
          ", coloured by deviation on the scale of the 2D maps (blue overcut, red material left, grey not "
          "evaluated)" +
          std::string(view.has_prediction ? "; the check box colours the surface with the predicted machining error "
                                            "(z-map error map) on the same scale"
                                          : "") +
          std::string(view.markers.empty() ? ""
                                           : "; wire spheres mark the predicted gouge sites (their extent on the "
                                             "surface) and the unexplained overcuts, coloured by status as in the "
                                             "Gouges section") +
          ". Drag to orbit, wheel to zoom, right-drag to pan.</p>\n";
  if (!view.markers.empty()) {
    html += "<ul class=\"view3d-markers\">";
    for (const PartView3d::Marker& m : view.markers) {
      char where[160];
      std::snprintf(where, sizeof where, " at %.2f, %.2f, %.2f mm, %.2f mm across", m.centre.x(), m.centre.y(),
                    m.centre.z(), 2 * m.radius);
      html += "<li><b>" + html::escape(m.label) + "</b> " + html::escape(m.status) + where + "</li>";
    }
    html += "</ul>\n";
  }
  html += "</div>\n";
  html += "<div class=\"view3d-static\">\n<p>The interactive view needs WebGL; the part in four views, the "
          "measured points coloured by deviation on the same scale (a grey ring where a view does not see the "
          "point):</p>\n" +
          static_view + "</div>\n";
  html += "<script type=\"application/json\" id=\"view3d-data\">" + part_view_3d_json(view) + "</script>\n";
  html += "<script>" + three + "\n</script>\n<script>" + orbit + "\n</script>\n<script>" + kViewerScript +
          "</script>\n</section>\n";
  fig.html = std::move(html);
  return fig;
}

}  // namespace furrow
