// The self-contained view (birdsim view): the scene is inlined in the page as JSON.
import { Viewer, publish } from "./viewer.js";

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

if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
else start();
