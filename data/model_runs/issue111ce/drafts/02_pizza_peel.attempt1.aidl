# Request (kitchen): a pizza peel for a home pizza oven, 6 mm birch ply. The blade is 320 mm
# wide and 300 mm deep: a straight back edge, straight sides 280 mm long and a front edge
# that is a shallow arc (20 mm proud of the sides' ends), its two front corners rounded r25
# and its back corners r10. A handle 45 mm wide runs 130 mm out of the back edge, its end
# fully round, with a 16 mm hanging hole concentric with that round end; where the handle
# meets the blade the corners are rounded r40. Five grip lines engraved across the handle
# (30 mm long, 8 mm apart), and "NONNA'S PIZZERIA" engraved filled in a serif font, 16 mm
# high, its middle 45 mm in front of the back edge.

thickness 6 mm

param blade_w = 320 mm, min = 250 mm, max = 400 mm
param blade_d = 300 mm, min = 250 mm, max = 360 mm
param handle_l = 130 mm, min = 100 mm, max = 200 mm
handle_w = 45 mm
crown = 20 mm        # how far the front arc stands proud of the sides' ends

solid peel {
    solid blade {
        back = Line((-blade_w / 2, 0), (blade_w / 2, 0))
        right = Line((blade_w / 2, 0), (blade_w / 2, blade_d - crown))
        front = Arc(start=(blade_w / 2, blade_d - crown), through=(0, blade_d),
                    end=(-blade_w / 2, blade_d - crown))
        left = Line((-blade_w / 2, blade_d - crown), (-blade_w / 2, 0))
    }
    solid handle {
        grip = RoundedRectangle(center=(0, -(handle_l - 10 mm) / 2), width=handle_w,
                                height=handle_l + 10 mm, corner_radius=handle_w / 2)
        hole hang {
            c = Circle(center=(0, -handle_l + handle_w / 2), diameter=16)
        }
        AlignCenterX(hang, grip)
        VerticalDistance(grip.bottom.midpoint, hang.c.center, handle_w / 2)
        drawing grips {
            g = Line((-15, -50), (15, -50))
            more = LinearPattern(g, 5, (0, -8))
        }
        AlignCenterX(grips, grip)
    }
    drawing label {
        t = Text("NONNA'S PIZZERIA", position=(0, 45), size=16, font="serif", valign="middle",
                 fill=true)
    }
    Fillet([blade.front, blade.right], 25)
    Fillet([blade.front, blade.left], 25)
    Fillet([blade.back, blade.right], 10)
    Fillet([blade.back, blade.left], 10)
    Fillet([blade.back, handle.grip], 40)

    assert blade.bb.width == 320 mm, "blade 320 wide"
    assert blade.front.through.y - blade.back.start.y == 300 mm, "blade 300 deep"
    assert blade.right.length == 280 mm, "straight sides 280"
    assert blade.back.start.y - handle.grip.bb.bottom == 130 mm, "handle 130 out of the blade"
    assert handle.grip.width == 45 mm, "handle 45 wide"
    assert handle.hang.c.diameter == 16 mm, "16 mm hanging hole"
    assert len(handle.grips.more) == 5, "five grip lines"
    assert label.t.position.y - blade.back.start.y == 45 mm, "label 45 in front of the back edge"
}
