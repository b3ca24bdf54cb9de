# Request (office): a magnetic conference name badge, two 3 mm acrylic layers glued
# together. Both layers are 76 x 40 mm with 6 mm rounded corners and share a 14 x 3.5 mm
# lanyard slot whose top edge is 3 mm below the badge's top edge, centred. Front layer:
# a hexagon logo 14 mm across the corners, engraved filled, its centre 12 mm in from the
# left edge; the name "ALEX MORGAN" in bold 7 mm letters engraved filled and the role
# "DESIGN TEAM" in 3.5 mm single-stroke letters under it, both starting 24 mm from the
# left edge and no closer than 3 mm to the right edge. Back layer: two 10.2 mm holes
# 40 mm apart, centred, 6 mm below the middle, for 10 x 3 mm disc magnets.

thickness 3 mm

param bw = 76 mm, min = 60 mm, max = 100 mm
param bh = 40 mm, min = 30 mm, max = 60 mm
param name = "ALEX MORGAN"
param role = "DESIGN TEAM"

def layer() -> solid {
    plate = RoundedRectangle(center=(0, 0), width=bw, height=bh, corner_radius=6)
    hole lanyard { s = Rectangle(center=(0, 0), width=14, height=3.5) }
    AlignCenterX(lanyard, plate)
    lanyard.bb.top == plate.bb.top - 3 mm
}

assembly badge {
    solid front {
        base = layer()
        drawing logo {
            hex = RegularPolygon(center=(0, 0), radius=7, sides=6, rotation=90 deg, fill=true)
        }
        drawing label {
            who = Text(name, position=(0, 0), size=7, anchor="start", valign="middle",
                       font="sans:Bold", fill=true, max_width=bw - 24 mm - 3 mm)
            what = Text(role, position=(0, -9), size=3.5, anchor="start")
        }
        HorizontalDistance(base.plate.bb.top_left, logo.hex.center, 12 mm)
        AlignCenterY(logo.hex.center, base.plate.center)
        HorizontalDistance(base.plate.bb.top_left, label.who.position, 24 mm)
        label.who.position.y == base.plate.center.y + 3 mm
        Rigid(label.who, label.what)
    }
    solid back {
        base = layer()
        hole magnets {
            m1 = Circle(center=(-20, -6), diameter=10.2)
            m2 = Circle(center=(20, -6), diameter=10.2)
        }
        HorizontalDistance(magnets.m1.center, magnets.m2.center, 40 mm)
        AlignCenterX(magnets, base.plate)
        magnets.m1.center.y == base.plate.center.y - 6 mm
    }
    RightOf(back, front, gap=6)
    AlignCenterY(back, front)

    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, 3))

    assert front.base.plate.bb.width == 76 mm and front.base.plate.bb.height == 40 mm, "76 x 40 badge"
    assert front.label.who.bb.right <= front.base.plate.bb.right - 3 mm, "name clear of the right edge by 3 mm"
    assert front.base.plate.bb.top - front.base.lanyard.bb.top == 3 mm, "slot 3 mm below the top"
    assert front.logo.hex.center.x - front.base.plate.bb.left == 12 mm, "logo 12 mm in"
    assert back.magnets.m2.center.x - back.magnets.m1.center.x == 40 mm, "magnets 40 mm apart"
    assert back.base.plate.center.y - back.magnets.m1.center.y == 6 mm, "magnets 6 mm below the middle"
}
