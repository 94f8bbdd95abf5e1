// The viewer bundle (view.js): three.js, uPlot and the viewer, exposed as
// window.BirdsimViewer for the studio page (studio.js, which carries no copy of them);
// on the self-contained view (birdsim view) it starts on the inlined scene.
import { Handles } from "./handles.js";
import { Viewer, publish } from "./viewer.js";

window.BirdsimViewer = { Viewer, publish, Handles };

function start() {
  const app = document.getElementById("app");
  try {
    const data = JSON.parse(document.getElementById("birdsim-scene").textContent);
    publish(new Viewer(app, data, { width: 800, height: 500 }));
  } catch (err) {
    const p = document.createElement("p");
    p.className = "bv-error";
    p.textContent = `the 3-D view cannot start: ${err.message}`;
    app.appendChild(p);
    throw err;
  }
}

function maybeStart() {
  if (document.getElementById("birdsim-scene")) start();
}

if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", maybeStart);
else maybeStart();
