#!/usr/bin/env python3
# Monkey test of the workstation window: random clicks, drags, wheel turns, keys and menu picks
# (xdotool, fixed seed) for a while; the window must survive, and the document must still save
# and reload. `--xvfb` starts a private Xvfb (CTest does); without it the script uses $DISPLAY.
#
# The random input never asks to quit or to replace the document (no Ctrl+Q/N/O, no File,
# Lessons or Exercises menu, no window close), so the scene opened at the start is the one saved
# at the end. The input
# sequence depends on the seed only; what the window does with it depends on timing (frames
# under a software rasteriser), so the run is reproducible in its input, not frame for frame.
import argparse
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

from gui_session import Session, display, sanitizer_report

# Keys the workstation or ImGui reacts to, and harmless others (typed into a focused field).
PLAIN_KEYS = ["f", "p", "1", "2", "3", "c", "n", "i", "k", "Escape", "Escape", "Tab", "Return",
              "BackSpace", "Left", "Right", "Up", "Down", "space", "minus", "period", "0", "5",
              "9", "a", "x", "y", "z", "e", "F11", "Delete", "Home", "End"]
CHORDS = ["ctrl+z", "ctrl+z", "ctrl+y", "ctrl+shift+z", "ctrl+a", "shift+Tab"]
# Menu labels right of File (New, Open, Quit), Lessons and Exercises (which open another
# document): the first of them, Edit, is found in the window's UI report.
MENU_BAR_HEIGHT = 22


class Monkey(Session):
    def __init__(self, isoparm, scene, seconds, seed, workdir):
        # Autosave every 5 s so the run exercises it too.
        super().__init__(isoparm, workdir, scene, ("--autosave-seconds", "5"))
        self.menus_left = None  # window pixels: never click or move left of this in the bar
        self.rng = random.Random(seed)
        self.seconds = seconds
        self.events = 0
        self.counts = {}

    # A random point below the menu bar, in window coordinates made screen coordinates.
    def point(self):
        return (self.x0 + self.rng.randrange(0, self.w),
                self.y0 + self.rng.randrange(MENU_BAR_HEIGHT + 2, self.h))

    def count(self, kind):
        self.events += 1
        self.counts[kind] = self.counts.get(kind, 0) + 1

    # Each event is a list of chained xdotool commands; a few events go to one xdotool process
    # (starting one costs ~60 ms here, more than an event). `click` is spelled as mousedown and
    # mouseup: xdotool's own click waits ~170 ms.
    @staticmethod
    def press(button, times=1):
        return ["mousedown", button, "mouseup", button] * times

    def random_click(self):
        x, y = self.point()
        self.count("click")
        return ["mousemove", x, y] + self.press(self.rng.choice([1, 1, 1, 3]),
                                                self.rng.choice([1, 1, 2]))

    def random_drag(self):
        x, y = self.point()
        button = self.rng.choice([1, 1, 3])
        axis = self.rng.choice([None, None, None, "x", "y", "z", "shift"])
        cmd = ["mousemove", x, y]
        if axis:
            cmd += ["keydown", axis]
        cmd += ["mousedown", button]
        for _ in range(self.rng.randrange(2, 8)):
            x = min(max(x + self.rng.randrange(-120, 121), self.x0), self.x0 + self.w - 1)
            y = min(max(y + self.rng.randrange(-120, 121), self.y0 + MENU_BAR_HEIGHT + 2),
                    self.y0 + self.h - 1)
            cmd += ["sleep", 0.03, "mousemove", x, y]
        cmd += ["sleep", 0.03, "mouseup", button]
        if axis:
            cmd += ["keyup", axis]
        self.count("drag")
        return cmd

    def random_wheel(self):
        x, y = self.point()
        self.count("wheel")
        return ["mousemove", x, y] + self.press(self.rng.choice([4, 5]), self.rng.randrange(1, 6))

    def random_key(self):
        self.count("key")
        if self.rng.random() < 0.2:
            return ["key", "--clearmodifiers", self.rng.choice(CHORDS)]
        return ["key", self.rng.choice(PLAIN_KEYS)]

    def random_menu(self):
        # A label of the menu bar right of File, then a point of its drop-down, then Escape in
        # case the click landed on nothing (a menu left open would follow the mouse to File).
        if self.menus_left is None:
            self.menus_left = int(self.rect("menu/Edit")[0])
        x = self.x0 + self.rng.randrange(self.menus_left + 4, min(self.w, self.menus_left + 380))
        self.count("menu")
        return (["mousemove", x, self.y0 + MENU_BAR_HEIGHT // 2] + self.press(1) +
                ["sleep", 0.15, "mousemove", x + self.rng.randrange(0, 160),
                 self.y0 + MENU_BAR_HEIGHT + self.rng.randrange(8, 320), "sleep", 0.1] +
                self.press(1) + ["sleep", 0.1, "key", "Escape"])

    def run(self):
        actions = [(self.random_click, 30), (self.random_drag, 25), (self.random_wheel, 8),
                   (self.random_key, 25), (self.random_menu, 12)]
        funcs = [a for a, _ in actions]
        weights = [w for _, w in actions]
        end = time.time() + self.seconds
        while time.time() < end:
            batch = []
            for _ in range(4):
                batch += self.rng.choices(funcs, weights)[0]()
                batch += ["sleep", self.rng.choice([0.0, 0.02, 0.05, 0.1])]
            self.xdo(*batch)
            if not self.alive():
                return False
        return self.alive()

    # Closes dialogs and leaves text fields, then Ctrl+S; True once the scene file was rewritten.
    def save(self):
        before = os.stat(self.scene).st_mtime_ns
        for attempt in range(4):
            for _ in range(3):
                self.xdo("key", "Escape")
                time.sleep(0.3)
            # A click on the status bar (no widget there) takes the focus from any field.
            self.xdo("mousemove", self.x0 + self.w // 2, self.y0 + self.h - 4)
            self.xdo("click", 1)
            time.sleep(0.5)
            self.xdo("key", "--clearmodifiers", "ctrl+s")
            for _ in range(20):
                time.sleep(0.5)
                if os.stat(self.scene).st_mtime_ns != before:
                    return True
        return False


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--isoparm", required=True)
    ap.add_argument("--scene", required=True)
    ap.add_argument("--seconds", type=float, default=60)
    ap.add_argument("--seed", type=int, default=9)
    ap.add_argument("--keep", action="store_true", help="keep the temporary folder")
    ap.add_argument("--screenshot", help="a PNG of the screen when the random input ends")
    ap.add_argument("--xvfb", action="store_true",
                    help="start a private Xvfb (it picks a free display itself, -displayfd)")
    args = ap.parse_args()
    with display(args.xvfb) as name:
        if not name:
            print("monkey: no display; pass --xvfb or set DISPLAY", file=sys.stderr)
            return 2
        return run_monkey(args)


def run_monkey(args):
    work = tempfile.mkdtemp(prefix="isoparm-monkey-")
    m = Monkey(args.isoparm, args.scene, args.seconds, args.seed, work)
    ok = True
    started = time.time()
    try:
        if not m.find_window():
            print("monkey: the window did not appear", file=sys.stderr)
            ok = False
        elif not m.run():
            print(f"monkey: the window died after {m.events} events "
                  f"(exit status {m.proc.returncode})", file=sys.stderr)
            ok = False
        duration = time.time() - started
        if args.screenshot and m.alive():
            subprocess.run(["import", "-window", "root", args.screenshot], check=False)
        print(f"monkey: seed {args.seed}, {m.events} events in {duration:.1f} s: "
              + ", ".join(f"{k} {v}" for k, v in sorted(m.counts.items())))
        if ok:
            if not m.save():
                print("monkey: Ctrl+S did not rewrite the scene", file=sys.stderr)
                ok = False
            elif not m.alive():
                print("monkey: the window died while saving", file=sys.stderr)
                ok = False
        if ok:
            # The saved scene loads: a headless render reads it with every check of a load.
            r = subprocess.run([args.isoparm, "render", m.scene, "--size", "320x200", "-o",
                                os.path.join(work, "reloaded.png")], capture_output=True,
                               text=True, env=m.env)
            if r.returncode != 0:
                print("monkey: the saved scene does not load:\n" + r.stderr, file=sys.stderr)
                ok = False
            else:
                print("monkey: saved and reloaded " + m.scene)
    finally:
        if m.alive():
            status = m.quit()
            print(f"monkey: window closed, exit status {status}")
        m.stderr.close()
        # Autosave ran (every 5 s, into the private state folder) and a normal exit removed
        # the session's recovery file.
        state = os.path.join(work, "state", "isoparm")
        if os.path.isdir(state):
            left = os.listdir(state)
            print(f"monkey: autosave wrote to {state}; files left after exit: {len(left)}")
            if left and m.proc.returncode == 0:
                print("monkey: a normal exit left recovery files: " + ", ".join(left),
                      file=sys.stderr)
                ok = False
        else:
            print("monkey: no autosave happened (the document never had unsaved changes "
                  "at a check)")
        text = open(m.stderr_path, errors="replace").read()
        if sanitizer_report(text):
            print("monkey: sanitizer report:\n" + text, file=sys.stderr)
            ok = False
        elif m.proc.returncode not in (0, -15):
            print(f"monkey: exit status {m.proc.returncode}:\n{text}", file=sys.stderr)
            ok = False
        if args.keep or not ok:
            print("monkey: files kept in " + work)
        else:
            shutil.rmtree(work, ignore_errors=True)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
