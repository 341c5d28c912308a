(define (problem t1) (:domain tank) (:objects a - tank) (:init (= (level a) 0)) (:goal (>= (level a) 2)))
