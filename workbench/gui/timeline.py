"""The timeline shared by every workflow: play, pause, scrub and speed over a sampled motion,
with plots of joint positions, velocities, accelerations and TCP speed beside it."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import Any

import numpy as np
import viser
import viser.uplot as uplot
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.gui.fields import NumberField, format_number, hide_slider_boxes
from workbench.service import SampledMotion

DEG_PER_RAD = 180.0 / np.pi  # display only
MM_PER_M = 1000.0  # display only
SPEEDS = ("0.25x", "0.5x", "1x", "2x", "4x")
# uPlot reads x as a date unless told otherwise: every plot with a non-time x axis uses this.
SECONDS: dict[str, uplot.Scale] = {"x": uplot.Scale(time=False)}
JOINT_COLORS = ("#e6194b", "#3cb44b", "#4363d8", "#f58231", "#911eb4", "#42a5a5")


class Timeline:
    """Play/pause, a time slider, a speed choice and four plots; `show(q)` poses the robot."""

    def __init__(
        self, server: viser.ViserServer, show: Callable[[NDArray[np.float64]], None]
    ) -> None:
        self.server = server
        self.show = show
        self.motion: SampledMotion | None = None
        self._limits = (np.ones(0), np.ones(0))
        self._convention: Any = None
        self._follow: Callable[[float], None] | None = None
        self._plot_folder: viser.GuiFolderHandle | None = None
        self._t = 0.0  # [s] the time shown: the slider's and the box's value in use
        self._playing = threading.Event()
        self._stop = threading.Event()
        s = server.gui
        self._style = hide_slider_boxes(server)  # typed numbers go through strict text boxes
        with s.add_folder("Timeline"):
            self.info = s.add_markdown("No motion yet: plan one in a workflow tab.")
            self.play = s.add_button("Play", icon=viser.Icon.PLAYER_PLAY, disabled=True)
            self.time_field = NumberField(
                server,
                "Time [s]",
                get=lambda: self._t,
                put=self._set_time,
                allowed=lambda: (
                    f"[0, {format_number(self.motion.duration)}] s"
                    if self.motion is not None
                    else "none until a motion is planned"
                ),
                slider=(0.0, 1.0, 0.01),
            )
            self.time = self.time_field.slider
            self.time.disabled = True
            self.speed = s.add_dropdown("Speed", options=SPEEDS, initial_value="1x")
            self.plots: list[viser.GuiUplotHandle] = []
        self.play.on_click(lambda _: self.toggle())
        self.time.on_update(self._on_time)
        self._thread = threading.Thread(target=self._run, name="timeline", daemon=True)
        self._thread.start()

    # -- loading --------------------------------------------------------------------------
    def load(
        self,
        motion: SampledMotion,
        *,
        robot: Any,
        follow: Callable[[float], None] | None = None,
    ) -> None:
        """Show `motion` on the timeline and its plots, at t = 0, paused.

        `robot` (the moving robot's model) gives the joint convention the plots show (the
        controller's, as the jog sliders and the programs do) and the velocity and
        acceleration limits that scale the plots to percent. `follow(t)` is called whenever the
        robot is posed at time `t` [s], for what moves with it (a carried part, a tool path
        marker); a later `load` replaces it.
        """
        self.pause()
        self.motion = motion
        self._limits = (
            np.asarray(robot.max_velocity, float),
            np.asarray(robot.max_acceleration, float),
        )
        self._convention = robot.convention
        self._follow = follow
        self.time.max = max(motion.duration, 0.01)
        self._t = 0.0
        self.time.value = 0.0  # type: ignore[misc]
        self.time.disabled = False
        self.play.disabled = False
        hits = int(motion.colliding.sum())
        coll = f", **{hits} colliding samples**" if hits else ", collision-free"
        self.info.content = f"**{motion.name}**: cycle time **{motion.duration:.3f} s**{coll}"
        for p in self.plots:
            p.remove()
        if self._plot_folder is not None:
            self._plot_folder.remove()
        self.plots = self._make_plots(motion)
        self._pose(0.0)
        self.time_field.refresh()  # the box's tooltip: the new motion's range

    def clear(self) -> None:
        """Drop the loaded motion and its plots (the project it came from was replaced)."""
        self.pause()
        self.motion, self._follow = None, None
        for p in self.plots:
            p.remove()
        if self._plot_folder is not None:
            self._plot_folder.remove()
        self.plots, self._plot_folder = [], None
        self._t = 0.0
        self.time.value = 0.0  # type: ignore[misc]
        self.time_field.refresh()
        self.time.disabled = True
        self.play.disabled = True
        self.info.content = "No motion yet: plan one in a workflow tab."

    def _pose(self, t: float) -> None:
        if self.motion is None:
            return
        self.show(self.motion.at(t))
        if self._follow is not None:
            self._follow(t)

    def _make_plots(self, m: SampledMotion) -> list[viser.GuiUplotHandle]:
        t = m.times
        dof = m.dof
        vel_lim, acc_lim = self._limits
        # display in the controller's convention: q_ctrl = sign * q + offset, rates times sign
        joints = self._convention.to_controller(m.joints)
        sign = np.asarray(self._convention.sign, float)
        joint_series = [
            uplot.Series(label=f"J{j + 1}", stroke=JOINT_COLORS[j % 6], width=1.5)
            for j in range(dof)
        ]
        limit = uplot.Series(label="limit", stroke="#888888", dash=(6.0, 4.0), width=1)
        neg_limit = uplot.Series(label="-limit", stroke="#888888", dash=(6.0, 4.0), width=1)
        x = uplot.Series(label="t [s]")
        plots = []
        self._plot_folder = self.server.gui.add_folder("Plots", expand_by_default=True)
        with self._plot_folder:
            plots.append(
                self.server.gui.add_uplot(
                    data=(t, *(joints[:, j] * DEG_PER_RAD for j in range(dof))),
                    series=(x, *joint_series),
                    title="Joint positions [deg, controller]",
                    aspect=1.6,
                    scales=SECONDS,
                )
            )
            for name, values, lim in (
                ("Joint velocities [% of limit]", m.velocity, vel_lim),
                ("Joint accelerations [% of limit]", m.acceleration, acc_lim),
            ):
                pct = values * sign / lim * 100.0
                ones = np.full_like(t, 100.0)
                plots.append(
                    self.server.gui.add_uplot(
                        data=(t, *(pct[:, j] for j in range(dof)), ones, -ones),
                        series=(x, *joint_series, limit, neg_limit),
                        title=name,
                        aspect=1.6,
                        scales=SECONDS,
                    )
                )
            speed = m.tcp_speed * MM_PER_M
            top = float(max(speed.max(), 1.0)) * 1.05
            plots.append(
                self.server.gui.add_uplot(
                    data=(t, speed, np.where(m.colliding, top, 0.0)),
                    series=(
                        x,
                        uplot.Series(label="TCP [mm/s]", stroke="#1f77b4", width=1.5),
                        uplot.Series(
                            label="collision",
                            stroke="#d62728",
                            fill="rgba(214,39,40,0.25)",
                            width=1,
                        ),
                    ),
                    title="TCP speed [mm/s] and collisions",
                    aspect=1.6,
                    scales=SECONDS,
                )
            )
        return plots

    # -- playback -----------------------------------------------------------------------------
    def toggle(self) -> None:
        """Play when paused, pause when playing."""
        if self._playing.is_set():
            self.pause()
        elif self.motion is not None:
            if self._t >= self.motion.duration - 1e-9:
                self._set_time(0.0)
            self._playing.set()
            self.play.label, self.play.icon = "Pause", viser.Icon.PLAYER_PAUSE

    def pause(self) -> None:
        """Stop playback where it is."""
        self._playing.clear()
        self.play.label, self.play.icon = "Play", viser.Icon.PLAYER_PLAY

    @property
    def playing(self) -> bool:
        """Return True while the motion plays."""
        return self._playing.is_set()

    def _set_time(self, t: float) -> None:
        """Scrub to t [s]; refused outside [0, duration] (the robot stays where it is)."""
        m = self.motion
        if m is None:
            raise InputError("Time [s]: no motion yet; plan one in a workflow tab")
        if not 0.0 <= t <= m.duration + 1e-9:
            raise InputError(
                f"Time [s]: {format_number(t)} s is outside the motion"
                f" [0, {format_number(m.duration)}] s"
            )
        self._t = round(min(t, m.duration), 4)
        if float(self.time.value) != self._t:
            self.time.value = self._t  # type: ignore[misc]  # fires _on_time: poses the robot
        else:
            self._pose(self._t)
            self.time_field.refresh()

    def _on_time(self, event: Any) -> None:
        if event.client is not None:
            return  # the time field commits what a page sends (or refuses it)
        self._t = float(self.time.value)  # set from here: bending and playback scrub so
        self._pose(self._t)
        self.time_field.refresh()

    def _run(self) -> None:
        last = time.monotonic()
        while not self._stop.is_set():
            time.sleep(1 / 30)
            now = time.monotonic()
            dt, last = now - last, now
            m = self.motion
            if not self._playing.is_set() or m is None:
                continue
            factor = float(self.speed.value.rstrip("x"))
            t = min(self._t + dt * factor, m.duration)
            try:
                self._set_time(t)  # poses the robot
            except InputError:  # the motion was replaced meanwhile
                self.pause()
                continue
            if t >= m.duration:
                self.pause()

    def close(self) -> None:
        """Stop the playback thread."""
        self._stop.set()
