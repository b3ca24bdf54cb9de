# Gear templates, imported by ../gear.aidl with `import "parts/gears.aidl"`.

# A spur gear with `teeth` trapezoid teeth of module `module` (the pitch
# diameter is module * teeth), a bore and a keyway. `phase` turns the teeth.
def spur_gear(teeth=12, module=2 mm, bore=6 mm, phase=0 deg,
              cx=0 mm, cy=0 mm) -> solid {
    pitch_r = module * teeth / 2
    root_r = pitch_r - 1.25 * module
    tip_r = pitch_r + module
    step = 360 deg / teeth

    hub = Circle(center=(cx, cy), radius=root_r)
    pitch = Circle(center=(cx, cy), radius=pitch_r, construction=true)
    Concentric(pitch, hub)

    # one trapezoid per tooth, wide at the root, narrow at the tip
    for i in range(teeth) {
        a = phase + i * step
        tooth = Polygon([(cx + (root_r - 0.5) * cos(a - 0.3 * step), cy + (root_r - 0.5) * sin(a - 0.3 * step)),
                         (cx + (root_r - 0.5) * cos(a + 0.3 * step), cy + (root_r - 0.5) * sin(a + 0.3 * step)),
                         (cx + tip_r * cos(a + 0.13 * step), cy + tip_r * sin(a + 0.13 * step)),
                         (cx + tip_r * cos(a - 0.13 * step), cy + tip_r * sin(a - 0.13 * step))])
    }

    hole bore_hole {
        b = Circle(center=(cx, cy), diameter=bore)
        key = Rectangle(center=(cx, cy + bore / 2), width=bore / 3, height=bore / 2)
    }
    Concentric(bore_hole.b, hub)
}

# A gear with lightening holes in its web (for larger gears).
def spoked_gear(teeth=30, module=2 mm, bore=8 mm, phase=0 deg, windows=5,
                cx=0 mm, cy=0 mm) -> solid {
    g = spur_gear(teeth=teeth, module=module, bore=bore, phase=phase, cx=cx, cy=cy)
    root_r = module * teeth / 2 - 1.25 * module
    web_r = (root_r + bore / 2) / 2  # halfway between the bore and the root
    hole lightening {
        ring = Circle(center=(cx, cy), radius=web_r, construction=true)
        for i in range(windows) {
            a = 90 deg + i * 360 deg / windows
            w = Circle(center=(cx + web_r * cos(a), cy + web_r * sin(a)),
                       radius=0.3 * (root_r - bore / 2))
            OnCircle(w.center, ring)
        }
    }
    Concentric(lightening.ring, g.hub)
}
