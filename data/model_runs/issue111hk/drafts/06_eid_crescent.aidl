# Request (holidays): a hanging Eid decoration for the front window, one piece of 4 mm gold
# mirror acrylic. A crescent moon 300 mm across: the outer circle 300 mm, the bite a 260 mm
# circle whose centre is 60 mm right of the moon's, the horn tips rounded 3 mm. A five-pointed
# star, 60 mm across its tips (inner radius 12 mm), centred on the upper horn's tip. Across the
# moon's open side "EID MUBARAK" in bold sans, 20 mm capitals, cut as the material: the letters
# stand on a 6 mm rail (overlapping their feet by 1 mm), their baseline 10 mm below the moon's
# centre, the text starting 4 mm clear of the moon's inner edge, the rail running on into the
# moon's band to x = -85 mm so the words hang from the moon. A 5 mm hole for the ribbon 12 mm
# below the moon's top.

units mm
thickness 4 mm

outer_d = 300 mm
bite_d = 260 mm
bite_dx = 60 mm
base_y = -10 mm
# where the bite's edge crosses the baseline (left side) and the horn tips
bite_left = bite_dx - sqrt((bite_d / 2) ** 2 - base_y ** 2)
tip_x = ((outer_d / 2) ** 2 - (bite_d / 2) ** 2 + bite_dx ** 2) / (2 * bite_dx)
tip_y = sqrt((outer_d / 2) ** 2 - tip_x ** 2)

solid decoration {
    solid moon {
        outer = Circle(center=(0, 0), diameter=outer_d)
        hole bite {
            c = Circle(center=(bite_dx, 0), diameter=bite_d)
        }
        Fillet([outer, bite.c], 3)
    }

    solid star {
        s = Star(center=(tip_x, tip_y), points=5, outer_radius=30, inner_radius=12)
    }

    solid words {
        word = Text("EID MUBARAK", (bite_left + 4 mm, base_y), size=20, font="sans:Bold",
                    anchor="start")
        rail = Rectangle(corner=(-85, base_y - 5 mm), opposite=(word.bb.right, base_y + 1 mm))
    }

    hole ribbon {
        c = Circle(center=(0, outer_d / 2 - 12 mm), diameter=5)
    }
}

assert abs(decoration.moon.outer.diameter - 300 mm) < 0.01 mm, "300 mm moon"
assert abs(decoration.moon.bite.c.center.x - decoration.moon.outer.center.x - 60 mm) < 0.01 mm, "bite 60 mm right"
assert abs(decoration.star.s.outer_radius * 2 - 60 mm) < 0.01 mm, "star 60 mm across its tips"
assert distance(decoration.star.s.center, polar(decoration.moon.outer.center, 150 mm, atan2(tip_y, tip_x))) < 0.01 mm,
    "star centred on the horn tip"
assert distance(decoration.words.word, decoration.moon) >= 3.9 mm, "letters clear of the moon"
assert decoration.words.rail.bb.left < bite_left - 10 mm, "rail reaches into the moon's band"
assert decoration.words.word.bb.right < decoration.moon.bb.right, "text within the moon's width"
assert abs(decoration.words.rail.bb.height - 6 mm) < 0.01 mm, "6 mm rail"
assert abs(decoration.moon.bb.top - decoration.ribbon.c.center.y - 12 mm) < 0.01 mm, "ribbon hole 12 mm below the top"
