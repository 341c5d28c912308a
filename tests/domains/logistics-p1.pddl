(define (problem logistics-2-2) (:domain logistics)
  (:objects city1 city2 - city pos1 pos2 - location apt1 apt2 - airport truck1 truck2 - truck plane1 - airplane
            pkg1 pkg2 pkg3 - package)
  (:init (in-city pos1 city1) (in-city apt1 city1) (in-city pos2 city2) (in-city apt2 city2)
         (at truck1 pos1) (at truck2 apt2) (at plane1 apt1)
         (at pkg1 pos1) (at pkg2 pos1) (at pkg3 apt2))
  (:goal (and (at pkg1 pos2) (at pkg2 apt2) (at pkg3 pos1))))
