# Request (science): a classroom puzzle of the Earth's layers to scale, 1 mm = 50 km, from
# 3 mm acrylic in colours, cut with 0.15 mm kerf allowance so the pieces press-fit:
# - inner core: a disc of radius 1220 km (24.4 mm), "INNER CORE" engraved across it;
# - outer core: a ring from 1220 to 3480 km (69.6 mm), "OUTER CORE" along its top and
#   "LIQUID IRON" along its bottom, "5150 km" at its inner edge on the right (depth);
# - mantle: a ring from 3480 km to the surface, 6371 km (127.42 mm), the 660 km boundary
#   (r = 114.2 mm) and the crust's base, 35 km deep (r = 126.72 mm), engraved as circles,
#   "LOWER MANTLE" along its top, "UPPER MANTLE" along its bottom between the 660 km line
#   and the crust, "2890 km" and "660 km" on the right at those boundaries;
# - a frame ring 15 mm wide round the mantle (0.2 mm clearance) and a back disc the frame's
#   size, glued together; both with a hanging tab at the top: a 16 mm round end 8 mm above
#   the frame with a 5 mm hole; "LAYERS OF THE EARTH" along the frame's top and
#   "1 mm = 50 km" along its bottom, 6 mm.

kerf 0.15 mm
thickness 3 mm
t = 3 mm

def km(d) = d / 50 * 1 mm    # the model's scale
R = km(6371)
r_outer_core = km(3480)
r_inner_core = km(1220)
r_660 = km(6371 - 660)
r_crust = km(6371 - 35)
frame_in = R + 0.2 mm
frame_out = frame_in + 15 mm

def hanger_outline() = Hull(Circle(center=(0, frame_out + 8 mm), radius=8 mm),
                            Rectangle(center=(0, frame_out - 10 mm), width=16 mm, height=4 mm))

assembly earth {
    solid inner_core {
        disc = Circle(center=(0, 0), radius=r_inner_core)
        Fixed(disc)
        drawing label {
            a = Text("INNER", position=(0, 1.5), size=4, anchor="middle")
            b = Text("CORE", position=(0, -5.5), size=4, anchor="middle")
        }
    }

    solid outer_core {
        ring = Circle(center=(0, 0), radius=r_outer_core)
        Fixed(ring)
        hole bore { c = Circle(center=(0, 0), radius=r_inner_core) }
        drawing label {
            top_base = Circle(center=(0, 0), radius=(r_inner_core + r_outer_core) / 2 - 2.5 mm,
                              construction=true)
            bottom_base = Circle(center=(0, 0), radius=(r_inner_core + r_outer_core) / 2 + 2.5 mm,
                                 construction=true)
            name = Text("OUTER CORE", along=top_base, size=5)
            what = Text("LIQUID IRON", along=bottom_base, size=5, flip=true)
            depth_base = Circle(center=(0, 0), radius=r_inner_core + 1.5 mm, construction=true)
            depth = Text("5150 km", along=depth_base, angle=0 deg, size=3)
        }
    }

    solid mantle {
        ring = Circle(center=(0, 0), radius=R)
        Fixed(ring)
        hole bore { c = Circle(center=(0, 0), radius=r_outer_core) }
        drawing lines {
            line_660 = Circle(center=(0, 0), radius=r_660)
            crust = Circle(center=(0, 0), radius=r_crust)
        }
        drawing label {
            lower_base = Circle(center=(0, 0), radius=(r_outer_core + r_660) / 2 - 3 mm,
                                construction=true)
            upper_base = Circle(center=(0, 0), radius=(r_660 + r_crust) / 2 + 2.5 mm,
                                construction=true)
            lower = Text("LOWER MANTLE", along=lower_base, size=6)
            upper = Text("UPPER MANTLE", along=upper_base, size=5, flip=true)
            d2890_base = Circle(center=(0, 0), radius=r_outer_core + 1.5 mm, construction=true)
            d2890 = Text("2890 km", along=d2890_base, angle=0 deg, size=3)
            d660_base = Circle(center=(0, 0), radius=r_660 + 1.5 mm, construction=true)
            d660 = Text("660 km", along=d660_base, angle=0 deg, size=3)
        }
    }

    solid frame {
        ring = Circle(center=(0, 0), radius=frame_out)
        Fixed(ring)
        tab = hanger_outline()
        hole opening { c = Circle(center=(0, 0), radius=frame_in) }
        hole hang { c = Circle(center=(0, frame_out + 8 mm), diameter=5 mm) }
        drawing label {
            base_top = Circle(center=(0, 0), radius=frame_in + 4.5 mm, construction=true)
            base_bottom = Circle(center=(0, 0), radius=frame_out - 4.5 mm, construction=true)
            title = Text("LAYERS OF THE EARTH", along=base_top, size=6)
            scale = Text("1 mm = 50 km", along=base_bottom, size=6, flip=true)
        }
    }

    solid back {
        disc = Circle(center=(0, 0), radius=frame_out)
        Fixed(disc)
        tab = hanger_outline()
        hole hang { c = Circle(center=(0, frame_out + 8 mm), diameter=5 mm) }
    }

    # flat on the sheet: each part beside the last
    RightOf(frame, back, gap=10)
    AlignBottom(frame, back)
    RightOf(mantle, frame, gap=10)
    AlignBottom(mantle, frame)
    RightOf(outer_core, mantle, gap=10)
    AlignBottom(outer_core, mantle)
    RightOf(inner_core, outer_core, gap=10)
    AlignBottom(inner_core, outer_core)

    # in 3D: the frame and the pieces on the back
    Place(back, position=(0, 0, 0))
    Place(frame, position=(0, 0, t))
    Place(mantle, position=(0, 0, t))
    Place(outer_core, position=(0, 0, t))
    Place(inner_core, position=(0, 0, t))

    # the request's numbers
    assert inner_core.disc.radius == 24.4 mm, "inner core 24.4 mm"
    assert outer_core.ring.radius == 69.6 mm and outer_core.bore.c.radius == 24.4 mm,
        "outer core 24.4 to 69.6"
    assert mantle.ring.radius == 127.42 mm and mantle.bore.c.radius == 69.6 mm,
        "mantle 69.6 to 127.42"
    assert abs(mantle.lines.line_660.radius - 114.2 mm) <= 0.05 mm, "660 km line at 114.2 (rounded)"
    assert mantle.lines.crust.radius == 126.72 mm, "crust line at 126.72"
    assert frame.opening.c.radius - mantle.ring.radius == 0.2 mm, "0.2 mm clearance"
    assert frame.ring.radius - frame.opening.c.radius == 15 mm, "frame 15 mm"
    assert frame.hang.c.center.y - frame.ring.radius == 8 mm, "hanging hole 8 mm above"
    assert frame.tab.bb.width == 16 mm, "16 mm round end"
    assert distance(mantle.label.upper, mantle.lines.line_660) >= 1 mm and
        distance(mantle.label.upper, mantle.lines.crust) >= 1 mm, "UPPER MANTLE in its band"
    assert distance(mantle.label.lower, mantle.lines.line_660) >= 1 mm and
        distance(mantle.label.lower, mantle.bore) >= 1 mm, "LOWER MANTLE in its band"
    assert distance(mantle.label.d660, mantle.lines.crust) >= 0.5 mm, "660 km label in its band"
    assert distance(outer_core.label, outer_core.bore) >= 0.5 mm, "outer core labels on it"
    assert distance(frame.label, frame.opening) >= 1 mm, "frame text on the frame"
    assert inner_core.label.bb.width <= 2 * r_inner_core - 8 mm, "INNER CORE fits"
}
