(define (problem os-sequencedstrips-p130_2)
(:domain openstacks-sequencedstrips-nonADL)
(:objects 
n0 n1 n2 n3 n4 n5 n6 n7 n8 n9 n10 n11 n12 n13 n14 n15 n16 n17 n18 n19 n20 n21 n22 n23 n24 n25 n26 n27 n28 n29 n30 n31 n32 n33 n34 n35 n36 n37 n38 n39 n40 n41 n42 n43 n44 n45 n46 n47 n48 n49 n50 n51 n52 n53 n54 n55 n56 n57 n58 n59 n60 n61 n62 n63 n64 n65 n66 n67 n68 n69 n70 n71 n72 n73 n74 n75 n76 n77 n78 n79 n80 n81 n82 n83 n84 n85 n86 n87 n88 n89 n90 n91 n92 n93 n94 n95 n96 n97 n98 n99 n100 n101 n102 n103 n104 n105 n106 n107 n108 n109 n110 n111 n112 n113 n114 n115 n116 n117 n118 n119 n120 n121 n122 n123 n124 n125 n126 n127 n128 n129 n130  - count
)

(:init
(next-count n0 n1) (next-count n1 n2) (next-count n2 n3) (next-count n3 n4) (next-count n4 n5) (next-count n5 n6) (next-count n6 n7) (next-count n7 n8) (next-count n8 n9) (next-count n9 n10) (next-count n10 n11) (next-count n11 n12) (next-count n12 n13) (next-count n13 n14) (next-count n14 n15) (next-count n15 n16) (next-count n16 n17) (next-count n17 n18) (next-count n18 n19) (next-count n19 n20) (next-count n20 n21) (next-count n21 n22) (next-count n22 n23) (next-count n23 n24) (next-count n24 n25) (next-count n25 n26) (next-count n26 n27) (next-count n27 n28) (next-count n28 n29) (next-count n29 n30) (next-count n30 n31) (next-count n31 n32) (next-count n32 n33) (next-count n33 n34) (next-count n34 n35) (next-count n35 n36) (next-count n36 n37) (next-count n37 n38) (next-count n38 n39) (next-count n39 n40) (next-count n40 n41) (next-count n41 n42) (next-count n42 n43) (next-count n43 n44) (next-count n44 n45) (next-count n45 n46) (next-count n46 n47) (next-count n47 n48) (next-count n48 n49) (next-count n49 n50) (next-count n50 n51) (next-count n51 n52) (next-count n52 n53) (next-count n53 n54) (next-count n54 n55) (next-count n55 n56) (next-count n56 n57) (next-count n57 n58) (next-count n58 n59) (next-count n59 n60) (next-count n60 n61) (next-count n61 n62) (next-count n62 n63) (next-count n63 n64) (next-count n64 n65) (next-count n65 n66) (next-count n66 n67) (next-count n67 n68) (next-count n68 n69) (next-count n69 n70) (next-count n70 n71) (next-count n71 n72) (next-count n72 n73) (next-count n73 n74) (next-count n74 n75) (next-count n75 n76) (next-count n76 n77) (next-count n77 n78) (next-count n78 n79) (next-count n79 n80) (next-count n80 n81) (next-count n81 n82) (next-count n82 n83) (next-count n83 n84) (next-count n84 n85) (next-count n85 n86) (next-count n86 n87) (next-count n87 n88) (next-count n88 n89) (next-count n89 n90) (next-count n90 n91) (next-count n91 n92) (next-count n92 n93) (next-count n93 n94) (next-count n94 n95) (next-count n95 n96) (next-count n96 n97) (next-count n97 n98) (next-count n98 n99) (next-count n99 n100) (next-count n100 n101) (next-count n101 n102) (next-count n102 n103) (next-count n103 n104) (next-count n104 n105) (next-count n105 n106) (next-count n106 n107) (next-count n107 n108) (next-count n108 n109) (next-count n109 n110) (next-count n110 n111) (next-count n111 n112) (next-count n112 n113) (next-count n113 n114) (next-count n114 n115) (next-count n115 n116) (next-count n116 n117) (next-count n117 n118) (next-count n118 n119) (next-count n119 n120) (next-count n120 n121) (next-count n121 n122) (next-count n122 n123) (next-count n123 n124) (next-count n124 n125) (next-count n125 n126) (next-count n126 n127) (next-count n127 n128) (next-count n128 n129) (next-count n129 n130) 
(stacks-avail n0)

(waiting o1)
(includes o1 p6)

(waiting o2)
(includes o2 p1)(includes o2 p18)(includes o2 p66)(includes o2 p101)(includes o2 p129)

(waiting o3)
(includes o3 p8)(includes o3 p35)(includes o3 p40)(includes o3 p79)(includes o3 p122)

(waiting o4)
(includes o4 p1)(includes o4 p61)

(waiting o5)
(includes o5 p8)(includes o5 p62)(includes o5 p70)

(waiting o6)
(includes o6 p51)(includes o6 p107)

(waiting o7)
(includes o7 p38)(includes o7 p51)(includes o7 p53)(includes o7 p72)(includes o7 p124)

(waiting o8)
(includes o8 p6)(includes o8 p30)

(waiting o9)
(includes o9 p57)

(waiting o10)
(includes o10 p4)(includes o10 p25)(includes o10 p84)

(waiting o11)
(includes o11 p4)(includes o11 p47)(includes o11 p72)(includes o11 p76)(includes o11 p99)

(waiting o12)
(includes o12 p32)(includes o12 p96)

(waiting o13)
(includes o13 p115)(includes o13 p126)

(waiting o14)
(includes o14 p11)(includes o14 p18)(includes o14 p58)(includes o14 p75)(includes o14 p78)

(waiting o15)
(includes o15 p6)(includes o15 p54)(includes o15 p59)(includes o15 p99)(includes o15 p108)(includes o15 p117)

(waiting o16)
(includes o16 p56)(includes o16 p58)(includes o16 p76)(includes o16 p91)(includes o16 p130)

(waiting o17)
(includes o17 p12)(includes o17 p24)

(waiting o18)
(includes o18 p3)(includes o18 p40)(includes o18 p104)

(waiting o19)
(includes o19 p53)

(waiting o20)
(includes o20 p17)(includes o20 p40)(includes o20 p82)

(waiting o21)
(includes o21 p78)

(waiting o22)
(includes o22 p59)(includes o22 p119)

(waiting o23)
(includes o23 p18)(includes o23 p74)(includes o23 p129)

(waiting o24)
(includes o24 p42)(includes o24 p55)(includes o24 p105)(includes o24 p129)

(waiting o25)
(includes o25 p114)

(waiting o26)
(includes o26 p1)(includes o26 p87)

(waiting o27)
(includes o27 p50)(includes o27 p123)

(waiting o28)
(includes o28 p28)(includes o28 p48)

(waiting o29)
(includes o29 p7)(includes o29 p23)(includes o29 p43)(includes o29 p69)(includes o29 p92)

(waiting o30)
(includes o30 p27)(includes o30 p67)(includes o30 p68)

(waiting o31)
(includes o31 p36)(includes o31 p95)(includes o31 p118)

(waiting o32)
(includes o32 p5)

(waiting o33)
(includes o33 p32)(includes o33 p58)(includes o33 p101)

(waiting o34)
(includes o34 p29)

(waiting o35)
(includes o35 p54)(includes o35 p55)(includes o35 p96)(includes o35 p117)(includes o35 p119)(includes o35 p126)

(waiting o36)
(includes o36 p52)(includes o36 p77)(includes o36 p79)(includes o36 p120)

(waiting o37)
(includes o37 p3)(includes o37 p13)(includes o37 p18)(includes o37 p61)(includes o37 p86)(includes o37 p95)(includes o37 p107)

(waiting o38)
(includes o38 p75)(includes o38 p77)(includes o38 p94)(includes o38 p128)

(waiting o39)
(includes o39 p74)(includes o39 p89)(includes o39 p102)

(waiting o40)
(includes o40 p10)(includes o40 p39)

(waiting o41)
(includes o41 p99)(includes o41 p109)(includes o41 p127)

(waiting o42)
(includes o42 p90)

(waiting o43)
(includes o43 p65)(includes o43 p94)

(waiting o44)
(includes o44 p13)(includes o44 p18)(includes o44 p34)(includes o44 p112)(includes o44 p120)

(waiting o45)
(includes o45 p73)(includes o45 p79)

(waiting o46)
(includes o46 p4)(includes o46 p31)(includes o46 p36)

(waiting o47)
(includes o47 p23)

(waiting o48)
(includes o48 p101)

(waiting o49)
(includes o49 p8)(includes o49 p103)(includes o49 p113)(includes o49 p118)

(waiting o50)
(includes o50 p5)(includes o50 p99)(includes o50 p103)

(waiting o51)
(includes o51 p23)(includes o51 p33)(includes o51 p78)

(waiting o52)
(includes o52 p4)(includes o52 p33)(includes o52 p46)(includes o52 p85)(includes o52 p124)

(waiting o53)
(includes o53 p22)(includes o53 p37)(includes o53 p45)

(waiting o54)
(includes o54 p101)

(waiting o55)
(includes o55 p48)

(waiting o56)
(includes o56 p10)(includes o56 p16)(includes o56 p35)(includes o56 p67)(includes o56 p77)(includes o56 p93)

(waiting o57)
(includes o57 p27)

(waiting o58)
(includes o58 p69)(includes o58 p73)(includes o58 p76)(includes o58 p111)(includes o58 p130)

(waiting o59)
(includes o59 p14)(includes o59 p27)(includes o59 p42)

(waiting o60)
(includes o60 p14)(includes o60 p82)

(waiting o61)
(includes o61 p9)(includes o61 p45)(includes o61 p52)(includes o61 p72)(includes o61 p102)(includes o61 p121)(includes o61 p126)

(waiting o62)
(includes o62 p8)

(waiting o63)
(includes o63 p80)

(waiting o64)
(includes o64 p10)

(waiting o65)
(includes o65 p69)

(waiting o66)
(includes o66 p62)(includes o66 p112)(includes o66 p121)

(waiting o67)
(includes o67 p37)(includes o67 p61)(includes o67 p73)

(waiting o68)
(includes o68 p4)(includes o68 p123)

(waiting o69)
(includes o69 p51)

(waiting o70)
(includes o70 p17)(includes o70 p54)(includes o70 p85)

(waiting o71)
(includes o71 p13)(includes o71 p15)(includes o71 p69)(includes o71 p94)(includes o71 p95)

(waiting o72)
(includes o72 p120)

(waiting o73)
(includes o73 p23)

(waiting o74)
(includes o74 p11)

(waiting o75)
(includes o75 p5)(includes o75 p82)

(waiting o76)
(includes o76 p85)(includes o76 p90)

(waiting o77)
(includes o77 p12)(includes o77 p76)(includes o77 p89)

(waiting o78)
(includes o78 p70)

(waiting o79)
(includes o79 p19)(includes o79 p40)(includes o79 p79)

(waiting o80)
(includes o80 p27)(includes o80 p75)

(waiting o81)
(includes o81 p9)(includes o81 p20)(includes o81 p47)(includes o81 p51)(includes o81 p75)(includes o81 p79)(includes o81 p125)

(waiting o82)
(includes o82 p122)

(waiting o83)
(includes o83 p51)(includes o83 p54)(includes o83 p102)(includes o83 p121)

(waiting o84)
(includes o84 p35)

(waiting o85)
(includes o85 p110)

(waiting o86)
(includes o86 p5)(includes o86 p24)(includes o86 p74)(includes o86 p81)(includes o86 p87)

(waiting o87)
(includes o87 p48)(includes o87 p86)(includes o87 p88)(includes o87 p95)

(waiting o88)
(includes o88 p23)(includes o88 p51)(includes o88 p83)(includes o88 p87)(includes o88 p99)

(waiting o89)
(includes o89 p75)

(waiting o90)
(includes o90 p2)(includes o90 p32)(includes o90 p96)

(waiting o91)
(includes o91 p112)(includes o91 p114)

(waiting o92)
(includes o92 p5)(includes o92 p81)(includes o92 p94)

(waiting o93)
(includes o93 p98)(includes o93 p102)

(waiting o94)
(includes o94 p58)

(waiting o95)
(includes o95 p2)(includes o95 p24)(includes o95 p47)(includes o95 p67)(includes o95 p88)(includes o95 p92)(includes o95 p93)(includes o95 p116)(includes o95 p120)

(waiting o96)
(includes o96 p43)(includes o96 p49)

(waiting o97)
(includes o97 p119)

(waiting o98)
(includes o98 p106)

(waiting o99)
(includes o99 p25)(includes o99 p114)

(waiting o100)
(includes o100 p4)(includes o100 p15)(includes o100 p23)(includes o100 p28)

(waiting o101)
(includes o101 p27)(includes o101 p61)(includes o101 p67)(includes o101 p97)(includes o101 p126)

(waiting o102)
(includes o102 p11)

(waiting o103)
(includes o103 p40)(includes o103 p60)(includes o103 p96)

(waiting o104)
(includes o104 p44)

(waiting o105)
(includes o105 p38)

(waiting o106)
(includes o106 p27)

(waiting o107)
(includes o107 p16)

(waiting o108)
(includes o108 p75)(includes o108 p107)

(waiting o109)
(includes o109 p18)(includes o109 p37)(includes o109 p111)(includes o109 p118)(includes o109 p127)

(waiting o110)
(includes o110 p26)(includes o110 p66)

(waiting o111)
(includes o111 p46)(includes o111 p48)(includes o111 p55)(includes o111 p94)

(waiting o112)
(includes o112 p37)(includes o112 p49)(includes o112 p73)(includes o112 p100)

(waiting o113)
(includes o113 p24)(includes o113 p27)(includes o113 p64)(includes o113 p70)(includes o113 p72)(includes o113 p89)

(waiting o114)
(includes o114 p44)(includes o114 p53)(includes o114 p70)(includes o114 p86)

(waiting o115)
(includes o115 p10)(includes o115 p53)(includes o115 p59)(includes o115 p108)

(waiting o116)
(includes o116 p2)(includes o116 p64)(includes o116 p97)

(waiting o117)
(includes o117 p42)(includes o117 p102)(includes o117 p104)(includes o117 p122)

(waiting o118)
(includes o118 p6)(includes o118 p25)(includes o118 p62)(includes o118 p125)

(waiting o119)
(includes o119 p4)(includes o119 p41)(includes o119 p119)

(waiting o120)
(includes o120 p43)(includes o120 p88)

(waiting o121)
(includes o121 p12)(includes o121 p31)(includes o121 p62)(includes o121 p74)(includes o121 p125)

(waiting o122)
(includes o122 p34)

(waiting o123)
(includes o123 p24)(includes o123 p72)(includes o123 p115)(includes o123 p123)

(waiting o124)
(includes o124 p28)(includes o124 p81)(includes o124 p117)(includes o124 p118)(includes o124 p119)

(waiting o125)
(includes o125 p1)(includes o125 p39)(includes o125 p63)(includes o125 p125)

(waiting o126)
(includes o126 p13)

(waiting o127)
(includes o127 p23)(includes o127 p33)(includes o127 p71)

(waiting o128)
(includes o128 p30)(includes o128 p67)

(waiting o129)
(includes o129 p100)(includes o129 p126)

(waiting o130)
(includes o130 p21)(includes o130 p72)(includes o130 p96)(includes o130 p129)

(= (total-cost) 0)

)

(:goal
(and
(shipped o1)
(shipped o2)
(shipped o3)
(shipped o4)
(shipped o5)
(shipped o6)
(shipped o7)
(shipped o8)
(shipped o9)
(shipped o10)
(shipped o11)
(shipped o12)
(shipped o13)
(shipped o14)
(shipped o15)
(shipped o16)
(shipped o17)
(shipped o18)
(shipped o19)
(shipped o20)
(shipped o21)
(shipped o22)
(shipped o23)
(shipped o24)
(shipped o25)
(shipped o26)
(shipped o27)
(shipped o28)
(shipped o29)
(shipped o30)
(shipped o31)
(shipped o32)
(shipped o33)
(shipped o34)
(shipped o35)
(shipped o36)
(shipped o37)
(shipped o38)
(shipped o39)
(shipped o40)
(shipped o41)
(shipped o42)
(shipped o43)
(shipped o44)
(shipped o45)
(shipped o46)
(shipped o47)
(shipped o48)
(shipped o49)
(shipped o50)
(shipped o51)
(shipped o52)
(shipped o53)
(shipped o54)
(shipped o55)
(shipped o56)
(shipped o57)
(shipped o58)
(shipped o59)
(shipped o60)
(shipped o61)
(shipped o62)
(shipped o63)
(shipped o64)
(shipped o65)
(shipped o66)
(shipped o67)
(shipped o68)
(shipped o69)
(shipped o70)
(shipped o71)
(shipped o72)
(shipped o73)
(shipped o74)
(shipped o75)
(shipped o76)
(shipped o77)
(shipped o78)
(shipped o79)
(shipped o80)
(shipped o81)
(shipped o82)
(shipped o83)
(shipped o84)
(shipped o85)
(shipped o86)
(shipped o87)
(shipped o88)
(shipped o89)
(shipped o90)
(shipped o91)
(shipped o92)
(shipped o93)
(shipped o94)
(shipped o95)
(shipped o96)
(shipped o97)
(shipped o98)
(shipped o99)
(shipped o100)
(shipped o101)
(shipped o102)
(shipped o103)
(shipped o104)
(shipped o105)
(shipped o106)
(shipped o107)
(shipped o108)
(shipped o109)
(shipped o110)
(shipped o111)
(shipped o112)
(shipped o113)
(shipped o114)
(shipped o115)
(shipped o116)
(shipped o117)
(shipped o118)
(shipped o119)
(shipped o120)
(shipped o121)
(shipped o122)
(shipped o123)
(shipped o124)
(shipped o125)
(shipped o126)
(shipped o127)
(shipped o128)
(shipped o129)
(shipped o130)
))

(:metric minimize (total-cost))

)

