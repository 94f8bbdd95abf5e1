// Plots linked to the timeline (uPlot): a vertical line at the viewer's time, and a
// click on a plot seeks there.
import uPlot from "uplot";

const COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"];

// Which plots a scene gets: [title, [[label, series key], ...]] (only series it has).
export function plotSpecs(data) {
  const s = data.series;
  const L = data.units.length;
  const specs = [
    [`position error [${L}]`, [["x - x_ref", "error_x"], ["z - z_ref", "error_z"]]],
    ["demanded force (one wing + drag, table units; Fz < 0 up)", [["Fx demand", "Fx_demand"], ["Fz demand", "Fz_demand"]]],
    ["achieved force (whole bird + weight, world; bird units)", [["force x", "force_x"], ["force z", "force_z"]]],
    ["power (both wings, bird units)", [["power", "power"]]],
    ["wingbeat parameters [rad]", data.param_names.map((n) => [n, n])],
    ["attitude [rad]", [["pitch", "pitch"], ["roll", "roll"], ["yaw", "yaw"]]],
  ];
  return specs
    .map(([title, list]) => [title, list.filter(([, key]) => key in s)])
    .filter(([, list]) => list.length > 0);
}

export function buildPlots(container, data, viewer) {
  const plots = [];
  const width = Math.max(240, container.clientWidth || 360);
  for (const [title, list] of plotSpecs(data)) {
    const div = document.createElement("div");
    div.className = "bv-plot";
    container.appendChild(div);
    const series = [{ label: `t [${data.units.time}]` }];
    const columns = [data.t];
    list.forEach(([label, key], k) => {
      series.push({ label, stroke: COLOURS[k % COLOURS.length], width: 1.5 });
      columns.push(data.series[key]);
    });
    const opts = {
      title,
      width,
      height: 150,
      series,
      legend: { show: true, live: false },
      cursor: { drag: { x: false, y: false } },
      scales: { x: { time: false } },
      axes: [{ size: 30 }, { size: 60 }],
    };
    const u = new uPlot(opts, columns, div);
    // the time cursor: a DOM line over the plot, moved without redrawing the plot
    const line = document.createElement("div");
    line.className = "bv-time";
    u.over.appendChild(line);
    u.timeLine = line;
    u.over.addEventListener("click", () => {
      if (u.cursor.left != null && u.cursor.left >= 0) viewer.seek(u.posToVal(u.cursor.left, "x"));
    });
    plots.push(u);
  }
  return {
    plots,
    redraw() {
      for (const u of plots) {
        const x = u.valToPos(viewer.time, "x");
        u.timeLine.style.transform = `translateX(${x}px)`;
      }
    },
  };
}
