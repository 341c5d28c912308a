(define (problem d1) (:domain der) (:objects a - thing) (:init) (:goal (ok a)))
